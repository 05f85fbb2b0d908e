/// @file
/// What the 2-D library peers (pixman, cairo) share: their y axis points down and their pixel
/// centres are at half-integers, and their coordinates have a limited range.
#pragma once

#include <span>
#include <string>

#include <glm/vec2.hpp>

#include "common/scene.hpp"

namespace tri::ch09 {

// [listing to_y_down]
/// Our pixel centre (i, j), y up, is the point (i + 1/2, H - 1 - j + 1/2) of a library whose
/// y axis points down from the top edge of the image and whose pixel centres are half-integers.
inline glm::dvec2 to_y_down(glm::dvec2 p, int height) noexcept {
  return {p.x + 0.5, (height - 1 - p.y) + 0.5};
}
// [/listing]

/// The pixels, in our coordinates, that a library could set for one triangle: its bounding box
/// grown by one pixel on every side (so a pixel set just outside still counts, as an error), cut
/// to the canvas. Empty (x_end <= x_begin) when it misses the canvas.
struct PixelWindow {
  int x_begin = 0, x_end = 0, y_begin = 0, y_end = 0;  ///< half-open ranges
};
PixelWindow pixels_around(const SceneTriangle& triangle, int width, int height) noexcept;

/// Throws std::runtime_error naming the peer and the limit when a vertex of the triangles,
/// mapped with to_y_down, lies outside [-limit, limit] on either axis: such a scene is refused,
/// never drawn with wrapped-around fixed-point coordinates.
void require_within(std::span<const SceneTriangle> triangles, int height, double limit,
                    const std::string& peer);

}  // namespace tri::ch09
