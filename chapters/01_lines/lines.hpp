/// @file
/// Four ways to draw a line segment between two pixel centres. Each draws every pixel of the
/// segment exactly once, both endpoints included, one pixel per step along the major axis.
#pragma once

#include <glm/vec2.hpp>

#include "common/canvas.hpp"
#include "common/color.hpp"

namespace tri::ch01 {

/// Gambetta's DrawLine: picks the axis along which the segment is longer, sorts the endpoints
/// along it and samples the other coordinate with interpolate(), rounding to the nearest pixel.
void draw_line_gambetta(Canvas& canvas, glm::ivec2 p0, glm::ivec2 p1, Color color);

/// The digital differential analyser: one step per pixel of the longer axis, adding the
/// per-step increment to both coordinates in floating point and rounding each to nearest.
/// Walks from p0 to p1, so a tie between two pixels may round differently in each direction.
void draw_line_dda(Canvas& canvas, glm::ivec2 p0, glm::ivec2 p1, Color color);

/// Bresenham's algorithm: integers only. An error term tracks twice the distance from the pixel
/// row to the true line, in units of 1/dx; all eight octants by swapping x and y for steep lines
/// and the endpoints for leftward ones. Ties round toward the endpoint with the smaller major
/// coordinate, so p0 -> p1 and p1 -> p0 give the same pixels. Only the steps whose major
/// coordinate lies on the canvas are walked: the error term at the first such step is computed
/// directly, so a line from -2^30 to 2^30 costs no more than the canvas is wide. Steps whose
/// other coordinate is off the canvas write nothing, so nothing is ever written outside.
void draw_line_bresenham(Canvas& canvas, glm::ivec2 p0, glm::ivec2 p1, Color color);

/// The midpoint algorithm: integers only, walking from p0 to p1 in the direction of each axis and
/// testing on which side of the line the midpoint between the two candidate pixels lies.
/// A midpoint exactly on the line keeps the minor coordinate, so ties round toward p0.
void draw_line_midpoint(Canvas& canvas, glm::ivec2 p0, glm::ivec2 p1, Color color);

}  // namespace tri::ch01
