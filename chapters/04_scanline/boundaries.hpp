/// @file
/// The arithmetic every scanline step shares: the vertices sorted by y, and where a boundary
/// crosses a row when its x is cut to an integer the way the article's `Vec2i` products are.
#pragma once

#include <cstdint>

#include <glm/vec2.hpp>

#include "chapters/03_interpolate_fill/sorted_triangle.hpp"

namespace tri::ch04 {

/// The vertices ordered from bottom to top, p0.y <= p1.y <= p2.y: the article's t0, t1, t2.
using ch03::SortedTriangle;

/// Orders the vertices by y with the article's three compare-and-swaps (t0/t1, t0/t2, t1/t2).
/// Vertices with equal y keep an order that depends on how they were passed in.
SortedTriangle sort_by_y(glm::ivec2 a, glm::ivec2 b, glm::ivec2 c) noexcept;

/// The x of the boundary from `start` to `end` after `step` of `steps` rows:
/// start.x + (end.x - start.x) * step / steps, with the quotient **truncated toward zero**, which
/// is what the article's int cast of `(end - start) * float(step) / steps` does. The quotient is
/// computed exactly in 64 bits, so float's own rounding never moves the cut (see the README).
/// Truncation pulls the result toward start.x: it is floor() on a boundary leaning right and
/// ceil() on one leaning left, never round().
/// Preconditions: steps > 0, 0 <= step <= steps, coordinates within ±2^30.
std::int64_t truncated_boundary_x(glm::ivec2 start, glm::ivec2 end, std::int64_t step,
                                  std::int64_t steps) noexcept;

}  // namespace tri::ch04
