/// @file
/// The five steps of Gambetta's DrawFilledTriangle (Listing 7-1), one function each, so that each
/// can be tested and drawn on its own. filled_triangle.hpp puts them together.
#pragma once

#include <cstddef>
#include <vector>

#include <glm/vec2.hpp>

#include "chapters/03_interpolate_fill/sorted_triangle.hpp"
#include "common/canvas.hpp"
#include "common/color.hpp"

namespace tri::ch03 {

/// The rows first..last, both included; empty when first > last.
struct RowRange {
  int first;
  int last;
  bool empty() const noexcept { return first > last; }
};

/// Step 1: sorts the vertices by y with the book's three conditional swaps. Vertices with equal
/// y keep their relative order, so a flat edge's two ends may come out either way round.
SortedTriangle sort_by_y(glm::ivec2 p0, glm::ivec2 p1, glm::ivec2 p2) noexcept;

/// Every row of the sorted triangle, y0..y2: the rows the book's arrays have.
RowRange triangle_rows(const SortedTriangle& t) noexcept;

/// The rows of the sorted triangle that lie on a canvas this tall (possibly empty): the only
/// rows the chapter's fill computes anything for.
RowRange visible_rows(const SortedTriangle& t, int canvas_height) noexcept;

/// Step 2's result: x of each edge at each row it spans, as x = f(y).
struct EdgeXs {
  std::vector<double> x01;  ///< short side P0-P1, one value per row
  std::vector<double> x12;  ///< short side P1-P2
  std::vector<double> x02;  ///< tall side P0-P2
};

/// Step 2: x01, x12 and x02 by chapter 01's tri::ch01::interpolate with y as the independent
/// variable. Only the rows in `rows` (clipped to each edge) are computed: with
/// triangle_rows(t) these are the book's three arrays, value for value; with a smaller range
/// each edge's x is first evaluated directly at the first and last row it keeps. A flat edge
/// (both ends on one row) gives the single value of its first end, as interpolate does.
/// Throws std::length_error when asked for more than max_canvas_side rows: clip first.
EdgeXs interpolate_edges(const SortedTriangle& t, RowRange rows);

/// Step 3: drops the last value of x01 (row y1, where x12 starts with the same x) and appends
/// x12, giving x012 with one value per row like x02. When clipping cut one of the two away there
/// is no shared row and nothing is dropped.
std::vector<double> concatenate_short_sides(std::vector<double> x01,
                                            const std::vector<double>& x12);

/// Step 4's result: x_left and x_right, the two ends of every row's span.
struct LeftRightXs {
  std::vector<double> x_left;
  std::vector<double> x_right;
};

/// The row the book compares x02 and x012 at: floor(length / 2).
std::size_t middle_row_index(std::size_t rows) noexcept;

/// Step 4: decides which of x02 and x012 is the left end by comparing them at the middle row.
/// Where they are equal there (a two-row triangle whose middle row is its apex), the first row
/// where they differ decides instead. If x02 is smaller it is the left end, otherwise x012 is
/// (also when the two never differ, as for collinear vertices).
LeftRightXs choose_left_right(std::vector<double> x02, std::vector<double> x012);

/// The column a real x lands on: nearest, halves up (like chapter 01's lines), clamped to
/// [-1, width] so that it always fits an int.
int nearest_column(double x, int width) noexcept;

/// Step 5: for row first_row + i, draws the pixels nearest_column(x_left[i]) through
/// nearest_column(x_right[i]), both included, as one horizontal span. Rows and spans are clipped
/// to the canvas before anything is drawn; a row whose left end rounds past its right end draws
/// nothing. Uses as many rows as the shorter of the two arrays has.
void draw_spans(Canvas& canvas, int first_row, const LeftRightXs& spans, Color color) noexcept;

}  // namespace tri::ch03
