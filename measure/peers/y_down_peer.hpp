/// @file
/// What the 2-D library peers (pixman, cairo) share: their y axis points down and their pixel
/// centres are at half-integers, and their coordinates have a limited range.
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <string>

#include <glm/vec2.hpp>

#include "common/canvas.hpp"
#include "common/scene.hpp"
#include "measure/error_metrics.hpp"

namespace tri {

// [listing to_y_down]
/// Our pixel centre (i, j), y up, is the point (i + 1/2, H - 1 - j + 1/2) of a library whose
/// y axis points down from the top edge of the image and whose pixel centres are half-integers.
inline glm::dvec2 to_y_down(glm::dvec2 p, int height) noexcept {
  return {p.x + 0.5, (height - 1 - p.y) + 0.5};
}
// [/listing]

/// A triangle's three vertices in such a library's space.
using YDownTriangle = std::array<glm::dvec2, 3>;

/// The triangle's vertices, each mapped with to_y_down.
inline YDownTriangle to_y_down(const SceneTriangle& triangle, int height) noexcept {
  return {to_y_down(triangle.vertices[0], height), to_y_down(triangle.vertices[1], height),
          to_y_down(triangle.vertices[2], height)};
}

/// The pixels, in our coordinates, that a library could set for one triangle: its bounding box
/// grown by one pixel on every side (so a pixel set just outside still counts, as an error), cut
/// to the canvas. Empty (x_end <= x_begin) when it misses the canvas.
struct PixelWindow {
  int x_begin = 0, x_end = 0, y_begin = 0, y_end = 0;  ///< half-open ranges
};
PixelWindow pixels_around(const SceneTriangle& triangle, int width, int height) noexcept;

/// The write counts of a library that draws into an image of its own, one triangle at a time:
/// for each triangle t, `draw_alone(t)` leaves only triangle t drawn on the image, and each pixel
/// of the window around it for which `is_set(x, top_row)` holds counts one write (so a pixel two
/// triangles cover counts 2, as for every other row of the report).
template <class DrawAlone, class IsSet>
WriteCounts count_each_alone(int width, int height, std::span<const SceneTriangle> triangles,
                             DrawAlone draw_alone, IsSet is_set) {
  WriteCounts result;
  result.counts.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0);
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    draw_alone(t);
    const PixelWindow window = pixels_around(triangles[t], width, height);
    for (int y = window.y_begin; y < window.y_end; ++y) {
      for (int x = window.x_begin; x < window.x_end; ++x) {
        if (is_set(x, height - 1 - y)) ++result.counts[pixel_index(x, y, width)];
      }
    }
  }
  return result;
}

/// Throws std::runtime_error naming the peer and the limit when a vertex of the triangles,
/// mapped with to_y_down, lies outside [-limit, limit] on either axis: such a scene is refused,
/// never drawn with wrapped-around fixed-point coordinates.
void require_within(std::span<const SceneTriangle> triangles, int height, double limit,
                    const std::string& peer);

}  // namespace tri
