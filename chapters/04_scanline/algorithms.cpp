#include "chapters/04_scanline/algorithms.hpp"

#include <array>

#include "chapters/04_scanline/scanline_fills.hpp"

namespace tri::ch04 {
namespace {

constexpr std::array<TriangleAlgorithm, 2> algorithms{{
    {.name = "scanline_two_loops",
     .chapter = "04_scanline",
     .rule = CoverageRule::approximate,
     .summary =
         "tinyrenderer's lower and upper loops; +1 heights, truncated span ends, row t1.y twice",
     .draw = draw_at_nearest_pixels<fill_two_loops>},
    {.name = "scanline_single_loop",
     .chapter = "04_scanline",
     .rule = CoverageRule::approximate,
     .summary =
         "tinyrenderer's single loop with second_half, top row included; truncated span ends",
     .draw = draw_at_nearest_pixels<fill_single_loop>},
}};

}  // namespace

std::span<const TriangleAlgorithm> triangle_algorithms() {
  return algorithms;
}

}  // namespace tri::ch04
