/// @file
/// Step 4 · exact area, fast: the per-edge areas of step 1, one pixel row at a time: the cells of
/// area and cover of FreeType's and AGG's anti-aliased scanline rasterizers, and the bands of a
/// row that need no cells, written four pixels at a time as the edges are stepped from row to row.
#pragma once

#include <algorithm>
#include <array>
#include <climits>
#include <vector>

#include "chapters/08_fast_exact/instruction_sets.hpp"
#include "chapters/09_anti_aliasing/coverage_canvas.hpp"
#include "common/triangle_algorithm.hpp"

namespace tri::ch09 {

/// How a triangle's coverage joins what the canvas already holds.
enum class Blend {
  sum,  ///< added: the triangles of a mesh add up to exactly 1 per pixel
  over  ///< composited as alpha, v + c (1 - v): what drawing with coverage as opacity does
};

/// One pixel row's cells: for each column, the area its edges leave on their right inside it,
/// and the height of the edges left of it ("cover"), which counts for its whole width. A
/// triangle's row holds two chains of edges, its left side and its right side; the cells each
/// touched are remembered, so the sum along the row reads only those and writes the pixels
/// between them at once. Kept between triangles so drawing allocates nothing once the widest row
/// has been seen; only the touched cells are summed and cleared, as AGG and FreeType do.
class RowCells {
 public:
  /// The two chains of a triangle's row: its left side and its right side.
  enum class Side { left, right };

  /// Starts an empty row of a canvas `width` wide.
  void start_row(int width);
  /// Adds the segment (x0, y0) -> (x1, y1) of the row's `side`, which lies within this row, to
  /// the cells it crosses; dy_dx is its edge's slope (infinite for a vertical edge).
  void add_segment(Side side, double x0, double y0, double x1, double y1, double dy_dx);
  /// Adds the coverage of the row's touched columns to row y of the canvas: the running sum of
  /// covers from the left plus each cell's own area, negated for a counter-clockwise outline.
  /// Between the two sides' cells no cell holds anything, so those pixels all get the cover;
  /// beyond the last touched column the covers have cancelled. Leaves the cells empty.
  void add_to_canvas(CoverageCanvas& canvas, int y, Blend blend = Blend::sum);

  /// What the row's edges left in a column since start_row (for figures and tests).
  double area(int column) const { return cells_[static_cast<std::size_t>(column)].area; }
  double cover(int column) const { return cells_[static_cast<std::size_t>(column)].cover; }

 private:
  struct Cell {
    double area = 0, cover = 0;
  };
  // The columns one side's segments touched since start_row (first > last: none).
  struct Touched {
    int first = INT_MAX, last = INT_MIN;
  };

  void add_segment_walk(Touched& touched, double x0, double y0, double x1, double y1, double dy_dx);
  void add_piece(Touched& touched, int column, double xa, double ya, double xb, double yb);
  template <class Put>
  void sum_along_row(float* row, Put put);
  template <class Put>
  double sum_cells(float* row, int first, int last, double cover, Put put);

  int width_ = 0;
  std::array<Touched, 2> touched_{};
  std::vector<Cell> cells_;  // width_ + 1: a piece in the last column leaves its cover beyond
};

/// Adds the parts of a triangle's three edges that lie in pixel row `row` (the band
/// row - 1/2 <= y <= row + 1/2) to the row's cells, walked counter-clockwise.
void add_edges_in_row(RowCells& cells, const Triangle& triangle, int row);

/// Step 4 · adds the triangle's coverage of every canvas pixel it reaches: its two sides are
/// walked from the bottom row to the top. Summed, each band of a row is written four or eight
/// pixels at a time (area_lane_floats(set)), each pixel's coverage from how much of it lies right
/// of each side (in floats: within 1e-6 of step 1's exact area in the tests); composited over, the
/// band is written as the running cover becomes known, and the row's cells serve where a piece
/// crosses the canvas's left or right edge, where the sides share cells, and in the row of the
/// middle vertex (within about 1e-12 before the canvas's float rounding). Right for every vertex
/// within ±2^30, subnormal differences included; a zero-area triangle, or one that
/// validate_triangle refuses (NaN, infinite, beyond ±2^30), adds nothing. The summed blend runs
/// the copy of its row loop for `set` (by default the widest the host runs; the tests force each).
void draw_triangle_area(CoverageCanvas& canvas, const Triangle& triangle, RowCells& cells,
                        Blend blend = Blend::sum,
                        ch08::InstructionSet set = ch08::widest_instruction_set());

/// How many floats the summed blend adds to a row at a time in the copy of its row loop for
/// `set`: 8 in the AVX2 copy (by default, on an x86-64 processor with AVX2), 4 in the portable one.
int area_lane_floats(ch08::InstructionSet set = ch08::widest_instruction_set()) noexcept;

/// Step 5 · the same coverage composited over the canvas as alpha, one triangle after another,
/// as a 2-D library does when it draws a mesh's triangles one by one with anti-aliasing on.
void draw_triangle_area_over(CoverageCanvas& canvas, const Triangle& triangle, RowCells& cells);

}  // namespace tri::ch09
