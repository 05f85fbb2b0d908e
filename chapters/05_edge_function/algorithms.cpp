#include "algorithms.hpp"

#include <array>

#include "edge_function_fill.hpp"

namespace tri::ch05 {

void draw_edge_function(Canvas& canvas, const Triangle& triangle, Color color) {
  fill_triangle_edge_function(canvas, nearest_pixel(triangle[0]), nearest_pixel(triangle[1]),
                              nearest_pixel(triangle[2]), color);
}

std::span<const TriangleAlgorithm> triangle_algorithms() {
  static constexpr std::array<TriangleAlgorithm, 1> algorithms{{
      {"edge_function", "05_edge_function", CoverageRule::inclusive,
       "bounding box clamped to the canvas, sign of the 2-D cross product per edge, either "
       "winding",
       draw_edge_function},
  }};
  return algorithms;
}

}  // namespace tri::ch05
