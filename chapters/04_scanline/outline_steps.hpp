/// @file
/// Steps 1 and 2 of the article: the triangle's outline, then the outline coloured by the two
/// boundaries a scanline fill walks once the vertices are sorted by y.
#pragma once

#include <glm/vec2.hpp>

#include "common/canvas.hpp"
#include "common/color.hpp"

namespace tri::ch04 {

/// Step 1: the three edges drawn with chapter 01's Bresenham line, nothing filled.
void draw_outline(Canvas& canvas, glm::ivec2 a, glm::ivec2 b, glm::ivec2 c, Color color);

/// Step 2: sorts the vertices by y into t0, t1, t2, then draws boundary B (t0 -> t1 -> t2, the
/// two short edges) in blue and boundary A (t0 -> t2, the long edge) in vermillion on top of it
/// (diagram_colors, as the figures show them).
void draw_sorted_boundaries(Canvas& canvas, glm::ivec2 a, glm::ivec2 b, glm::ivec2 c);

}  // namespace tri::ch04
