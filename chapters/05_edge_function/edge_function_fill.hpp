/// @file
/// Step 4 of the edge-function fill: test every pixel of the clamped bounding box, paint those
/// inside.
#pragma once

#include <glm/vec2.hpp>

#include "common/canvas.hpp"
#include "common/color.hpp"

namespace tri::ch05 {

/// Fills triangle abc (integer vertices at pixel centres, either winding): every pixel centre of
/// bounding_box_on_canvas() for which inside_triangle() holds is painted once, so the edges and
/// vertices are included. A zero-area triangle paints the pixel centres lying exactly on its
/// segment (a single pixel when all three vertices coincide). Never writes outside the canvas,
/// and visits at most width x height pixels, however far away the vertices are (within ±2^30).
void fill_triangle_edge_function(Canvas& canvas, glm::ivec2 a, glm::ivec2 b, glm::ivec2 c,
                                 Color color);

/// The same fill with inside_triangle_published_bug(): what the published code draws (never
/// registered; for the chapter's figure and tests).
void fill_triangle_published_bug(Canvas& canvas, glm::ivec2 a, glm::ivec2 b, glm::ivec2 c,
                                 Color color);

}  // namespace tri::ch05
