/// @file
/// Step 1 of the edge-function fill: the pixels worth testing, the triangle's bounding box cut
/// down to the canvas.
#pragma once

#include <glm/vec2.hpp>

namespace tri::ch05 {

/// An inclusive range of pixels: every (x, y) with min.x <= x <= max.x and min.y <= y <= max.y.
/// Loops over it use `<=`: the row and column of the top and right vertices belong to it.
struct PixelBox {
  glm::ivec2 min;
  glm::ivec2 max;

  /// True when the box holds no pixel (the triangle lies entirely off the canvas).
  bool empty() const noexcept { return min.x > max.x || min.y > max.y; }
};

/// The smallest box of pixel centres holding the vertices a, b and c, clamped to the pixels of
/// a width x height canvas (0..width-1, 0..height-1). Vertices may lie anywhere an int reaches,
/// e.g. at ±2^30: only min, max and clamping are done, so nothing can overflow, and the box never
/// holds more than width x height pixels. A triangle entirely off the canvas gives an empty box
/// (min > max on some axis) rather than a box squashed onto the border.
PixelBox bounding_box_on_canvas(glm::ivec2 a, glm::ivec2 b, glm::ivec2 c, int width, int height);

}  // namespace tri::ch05
