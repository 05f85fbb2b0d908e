#include "chapters/05_edge_function/algorithms.hpp"

#include <array>

#include "chapters/05_edge_function/edge_function_fill.hpp"

namespace tri::ch05 {

std::span<const TriangleAlgorithm> triangle_algorithms() {
  static constexpr auto algorithms = std::to_array<TriangleAlgorithm>({
      {.name = "edge_function",
       .chapter = "05_edge_function",
       .rule = CoverageRule::inclusive,
       .summary =
           "bounding box clamped to the canvas, sign of the 2-D cross product per edge, either "
           "winding",
       .draw = draw_at_nearest_pixels<fill_triangle_edge_function>},
  });
  return algorithms;
}

}  // namespace tri::ch05
