#include "chapters/07_exact_coverage/algorithms.hpp"

#include <array>

#include "chapters/07_exact_coverage/coverage_oracle.hpp"
#include "chapters/07_exact_coverage/fixed_point.hpp"

namespace tri::ch07 {

std::span<const TriangleAlgorithm> triangle_algorithms() {
  static constexpr std::array<TriangleAlgorithm, 5> algorithms{{
      {"exact_oracle", "07_exact_coverage", CoverageRule::top_left,
       "the truth: every pixel of the bounding box tested on its own with exact orientation signs",
       draw_triangle_oracle},
      {"fixed_point_8", "07_exact_coverage", CoverageRule::top_left,
       "vertices snapped to 1/256 pixel, integer edge functions, top-left bias (exact on that "
       "grid)",
       draw_triangle_fixed_point_8},
      {"fixed_point_4", "07_exact_coverage", CoverageRule::approximate,
       "fixed_point_8 with 4 fractional bits: vertices snapped to 1/16 pixel",
       draw_triangle_fixed_point_4},
      {"fixed_point_2", "07_exact_coverage", CoverageRule::approximate,
       "fixed_point_8 with 2 fractional bits: vertices snapped to 1/4 pixel",
       draw_triangle_fixed_point_2},
      {"fixed_point_0", "07_exact_coverage", CoverageRule::approximate,
       "fixed_point_8 with no fractional bits: vertices snapped to pixel centres",
       draw_triangle_fixed_point_0},
  }};
  return algorithms;
}

}  // namespace tri::ch07
