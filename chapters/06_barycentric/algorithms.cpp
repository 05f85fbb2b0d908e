#include "algorithms.hpp"

#include <array>
#include <concepts>

#include "fill.hpp"

namespace tri::ch06 {
namespace {

// The articles work on whole pixels, so the vertices are rounded to the nearest pixel centre.
template <std::floating_point Scalar>
void draw_barycentric(Canvas& canvas, const Triangle& triangle, Color color) {
  fill_triangle_barycentric<Scalar>(canvas, nearest_pixel(triangle[0]), nearest_pixel(triangle[1]),
                                    nearest_pixel(triangle[2]), color);
}

constexpr std::array<TriangleAlgorithm, 2> algorithms{{
    {"barycentric_float", "06_barycentric", CoverageRule::approximate,
     "bounding box, barycentric weights from one cross product in float", draw_barycentric<float>},
    {"barycentric_double", "06_barycentric", CoverageRule::approximate,
     "bounding box, barycentric weights from one cross product in double",
     draw_barycentric<double>},
}};

}  // namespace

std::span<const TriangleAlgorithm> triangle_algorithms() {
  return algorithms;
}

}  // namespace tri::ch06
