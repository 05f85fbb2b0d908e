#include "algorithms.hpp"

#include <array>

#include "scanline_fills.hpp"

namespace tri::ch04 {
namespace {

// The article's fills work on integer pixel positions: round each vertex to its nearest centre.
void draw_scanline_two_loops(Canvas& canvas, const Triangle& triangle, Color color) {
  fill_two_loops(canvas, nearest_pixel(triangle[0]), nearest_pixel(triangle[1]),
                 nearest_pixel(triangle[2]), color);
}

void draw_scanline_single_loop(Canvas& canvas, const Triangle& triangle, Color color) {
  fill_single_loop(canvas, nearest_pixel(triangle[0]), nearest_pixel(triangle[1]),
                   nearest_pixel(triangle[2]), color);
}

constexpr std::array<TriangleAlgorithm, 2> algorithms{{
    {"scanline_two_loops", "04_scanline", CoverageRule::approximate,
     "tinyrenderer's lower and upper loops; +1 heights, truncated span ends, row t1.y twice",
     draw_scanline_two_loops},
    {"scanline_single_loop", "04_scanline", CoverageRule::approximate,
     "tinyrenderer's single loop with second_half, top row included; truncated span ends",
     draw_scanline_single_loop},
}};

}  // namespace

std::span<const TriangleAlgorithm> triangle_algorithms() {
  return algorithms;
}

}  // namespace tri::ch04
