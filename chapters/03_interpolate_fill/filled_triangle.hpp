/// @file
/// Gambetta's DrawFilledTriangle: the five steps of fill_steps.hpp in a row.
#pragma once

#include <glm/vec2.hpp>

#include "common/canvas.hpp"
#include "common/color.hpp"

namespace tri::ch03 {

/// Fills the triangle p0 p1 p2 (pixel centres, any order, either winding) with one horizontal
/// span per row from y0 to y2, ends rounded to the nearest column. Two departures from the book:
/// the rows are clipped to the canvas before step 2, so the arrays are never taller than the
/// canvas (the book allocates them for every row of the triangle); and a triangle whose three
/// vertices share one row is drawn as one span from the leftmost to the rightmost vertex (the
/// book's arrays would keep only P0 and P1 there). Safe for any vertices within ±2^30: no
/// write leaves the canvas and the work is bounded by the canvas size.
void draw_filled_triangle(Canvas& canvas, glm::ivec2 p0, glm::ivec2 p1, glm::ivec2 p2, Color color);

}  // namespace tri::ch03
