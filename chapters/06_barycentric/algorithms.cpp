#include "chapters/06_barycentric/algorithms.hpp"

#include <array>

#include "chapters/06_barycentric/fill.hpp"

namespace tri::ch06 {
namespace {

// [listing registered]
constexpr std::array<TriangleAlgorithm, 2> algorithms{{
    {.name = "barycentric_float",
     .chapter = "06_barycentric",
     .rule = CoverageRule::approximate,
     .summary = "bounding box, barycentric weights from one cross product in float",
     .draw = draw_at_nearest_pixels<fill_triangle_barycentric<float>>,
     .precision_family = "barycentric",
     .precision_bits = 24},
    {.name = "barycentric_double",
     .chapter = "06_barycentric",
     .rule = CoverageRule::approximate,
     .summary = "bounding box, barycentric weights from one cross product in double",
     .draw = draw_at_nearest_pixels<fill_triangle_barycentric<double>>,
     .precision_family = "barycentric",
     .precision_bits = 53,
     .role = Role::speed_baseline},
}};
// [/listing]

}  // namespace

std::span<const TriangleAlgorithm> triangle_algorithms() {
  return algorithms;
}

}  // namespace tri::ch06
