#include "chapters/07_exact_coverage/algorithms.hpp"

#include <array>

#include "chapters/07_exact_coverage/coverage_oracle.hpp"
#include "chapters/07_exact_coverage/fixed_point.hpp"

namespace tri::ch07 {

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
      {.name = "fixed_point_4",
       .chapter = "07_exact_coverage",
       .rule = CoverageRule::approximate,
       .summary = "fixed_point_8 with 4 fractional bits: vertices snapped to 1/16 pixel",
       .draw = draw_triangle_fixed_point_with<4>,
       .precision_family = "fixed_point",
       .precision_bits = 4},
      {.name = "fixed_point_2",
       .chapter = "07_exact_coverage",
       .rule = CoverageRule::approximate,
       .summary = "fixed_point_8 with 2 fractional bits: vertices snapped to 1/4 pixel",
       .draw = draw_triangle_fixed_point_with<2>,
       .precision_family = "fixed_point",
       .precision_bits = 2},
      {.name = "fixed_point_0",
       .chapter = "07_exact_coverage",
       .rule = CoverageRule::approximate,
       .summary = "fixed_point_8 with no fractional bits: vertices snapped to pixel centres",
       .draw = draw_triangle_fixed_point_with<0>,
       .precision_family = "fixed_point",
       .precision_bits = 0},
  });
  return algorithms;
}

}  // namespace tri::ch07
