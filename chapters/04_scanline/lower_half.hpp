/// @file
/// Steps 3 and 4 of the article: the lower half of the triangle (rows t0.y to t1.y), first as the
/// two boundary points of each row, then filled between them.
#pragma once

#include <cstdint>

#include <glm/vec2.hpp>

#include "chapters/04_scanline/boundaries.hpp"
#include "common/canvas.hpp"
#include "common/color.hpp"

namespace tri::ch04 {

/// Where one row meets the two boundaries: x on boundary A (t0 -> t2) and on boundary B.
struct SpanEnds {
  std::int64_t a;
  std::int64_t b;
};

/// The ends of row y of the lower half as the article computes them: A at (y - t0.y) / total
/// height of the way from t0 to t2, B at (y - t0.y) / (t1.y - t0.y **+ 1**) of the way from t0 to
/// t1. The +1 keeps the division defined when t0.y == t1.y, at a price: B stops short of t1.
/// Preconditions: t0.y < t2.y and t0.y <= y <= t1.y.
SpanEnds lower_half_ends(const SortedTriangle& t, std::int64_t y) noexcept;

/// Step 3: for every row of the lower half, only the point on boundary A (vermillion) and the point
/// on boundary B (blue). Rows are one pixel apart but the points are not, so a shallow boundary
/// shows gaps. Draws nothing when all three vertices share a row (the article divides 0 by 0).
void draw_lower_half_boundary_points(Canvas& canvas, glm::ivec2 a, glm::ivec2 b, glm::ivec2 c);

/// The ends of row y of one half of a sorted triangle: lower_half_ends, or step 5's
/// upper_half_ends.
using HalfEnds = SpanEnds (*)(const SortedTriangle& t, std::int64_t y) noexcept;

/// The loop of steps 4 and 5: every row from `low` to `high` that lies on the canvas, filled from
/// its A end to its B end as `ends` gives them, both included.
void fill_half(Canvas& canvas, const SortedTriangle& t, std::int64_t low, std::int64_t high,
               HalfEnds ends, Color color);

/// Step 4: the same rows, each filled from its A point to its B point, both included, which
/// closes the gaps. Draws nothing when all three vertices share a row.
void fill_lower_half(Canvas& canvas, glm::ivec2 a, glm::ivec2 b, glm::ivec2 c, Color color);

}  // namespace tri::ch04
