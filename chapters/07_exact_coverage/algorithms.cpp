#include "chapters/07_exact_coverage/algorithms.hpp"

#include <array>

#include "chapters/07_exact_coverage/coverage_oracle.hpp"
#include "chapters/07_exact_coverage/fixed_point.hpp"

namespace tri::ch07 {
namespace {

// fixed_point_8 on a grid of `bits` fractional bits: the snapping alone differs, and on a coarser
// grid than the oracle's the result is approximate.
template <int bits>
constexpr TriangleAlgorithm coarser_grid(std::string_view name, std::string_view summary) {
  return {.name = name,
          .chapter = "07_exact_coverage",
          .rule = CoverageRule::approximate,
          .summary = summary,
          .draw = draw_triangle_fixed_point_with<bits>,
          .precision_family = "fixed_point",
          .precision_bits = bits};
}

}  // namespace

std::span<const TriangleAlgorithm> triangle_algorithms() {
  static constexpr auto algorithms = std::to_array<TriangleAlgorithm>({
      {.name = "exact_oracle",
       .chapter = "07_exact_coverage",
       .rule = CoverageRule::top_left,
       .summary = "the truth: every pixel of the bounding box tested on its own with exact "
                  "orientation signs",
       .draw = draw_triangle_oracle,
       .draw_rows = draw_triangle_oracle_rows,
       .role = Role::oracle},
      {.name = "fixed_point_8",
       .chapter = "07_exact_coverage",
       .rule = CoverageRule::top_left,
       .summary =
           "vertices snapped to 1/256 pixel, integer edge functions, top-left bias (exact on that "
           "grid)",
       .draw = draw_triangle_fixed_point_8,
       .precision_family = "fixed_point",
       .precision_bits = 8,
       .role = Role::fast_exact_starting},
      coarser_grid<4>("fixed_point_4",
                      "fixed_point_8 with 4 fractional bits: vertices snapped to 1/16 pixel"),
      coarser_grid<2>("fixed_point_2",
                      "fixed_point_8 with 2 fractional bits: vertices snapped to 1/4 pixel"),
      coarser_grid<0>("fixed_point_0",
                      "fixed_point_8 with no fractional bits: vertices snapped to pixel centres"),
  });
  return algorithms;
}

}  // namespace tri::ch07
