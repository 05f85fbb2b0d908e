/// @file
/// Steps 5 and 6 of the article: the whole triangle, first with a second loop for the upper half,
/// then with one loop over all rows that switches boundary B at t1 (`second_half`).
#pragma once

#include <cstdint>

#include <glm/vec2.hpp>

#include "chapters/04_scanline/boundaries.hpp"
#include "chapters/04_scanline/lower_half.hpp"
#include "common/canvas.hpp"
#include "common/color.hpp"

namespace tri::ch04 {

/// The ends of row y of the upper half as the article's second loop computes them: A as in the
/// lower half, B at (y - t1.y) / (t2.y - t1.y **+ 1**) of the way from t1 to t2, so B stops short
/// of t2. Preconditions: t0.y < t2.y and t1.y <= y <= t2.y.
SpanEnds upper_half_ends(const SortedTriangle& t, std::int64_t y) noexcept;

/// Step 5: the lower-half loop over rows t0.y..p1.y, then a second loop over rows t1.y..p2.y,
/// both with the article's +1 segment heights. Row t1.y belongs to both loops and is drawn twice.
/// Draws nothing when all three vertices share a row.
void fill_two_loops(Canvas& canvas, glm::ivec2 a, glm::ivec2 b, glm::ivec2 c, Color color);

/// The ends of the i-th row above t0 in the single loop: B runs t0 -> t1 while i <= t1.y - t0.y
/// and t1 -> t2 after (`second_half`, also taken from the first row when t0.y == t1.y), each over
/// its exact height. That choice never divides by zero.
/// Preconditions: t0.y < t2.y and 0 <= i <= t2.y - t0.y.
SpanEnds single_loop_ends(const SortedTriangle& t, std::int64_t i) noexcept;

/// Step 6, with the top row: one loop over rows t0.y..p2.y **inclusive**. Draws nothing when all
/// three vertices share a row (the article's early return).
void fill_single_loop(Canvas& canvas, glm::ivec2 a, glm::ivec2 b, glm::ivec2 c, Color color);

/// Step 6 exactly as published: the loop runs i < total height, so row t2.y, the top vertex or
/// the whole top edge, is never drawn. Kept to show and count what that bound loses.
void fill_single_loop_as_published(Canvas& canvas, glm::ivec2 a, glm::ivec2 b, glm::ivec2 c,
                                   Color color);

}  // namespace tri::ch04
