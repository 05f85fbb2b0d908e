/// @file
/// Step 4 · exact area, fast: the per-edge areas of step 1, deposited into one pixel row of
/// cells at a time and summed along the row, in doubles (the method of FreeType's and AGG's
/// anti-aliased scanline rasterizers).
#pragma once

#include <algorithm>
#include <array>
#include <vector>

#include "chapters/10_coverage/coverage_canvas.hpp"
#include "common/triangle_algorithm.hpp"

namespace tri::ch10 {

/// How a triangle's coverage joins what the canvas already holds.
enum class Blend {
  sum,  ///< added: the triangles of a mesh add up to exactly 1 per pixel
  over  ///< composited as alpha, v + c (1 - v): what drawing with coverage as opacity does
};

/// One pixel row's cells: for each column, the area its edges leave on their right inside it,
/// and the height of the edges left of it ("cover"), which counts for its whole width. Kept
/// between triangles so drawing allocates nothing once the widest row has been seen; only the
/// columns the edges touched are summed and cleared, as AGG and FreeType do.
class RowCells {
 public:
  /// Starts an empty row of a canvas `width` wide.
  void start_row(int width);
  /// Adds the segment (x0, y0) -> (x1, y1), which lies within this row, to the cells it crosses.
  /// A row holds at most four segments (a triangle's has at most three).
  void add_segment(double x0, double y0, double x1, double y1);
  /// The same with the segment's slope dy/dx given (its edge's, computed once per triangle).
  void add_segment(double x0, double y0, double x1, double y1, double dy_dx);
  /// Adds the coverage of the row's touched columns to row y of the canvas: the running sum of
  /// covers from the left plus each cell's own area, negated for a counter-clockwise outline.
  /// Beyond the last touched column the covers have cancelled. Leaves the cells empty.
  void add_to_canvas(CoverageCanvas& canvas, int y, Blend blend = Blend::sum);

  /// What the row's edges left in a column since start_row (for figures and tests).
  double area(int column) const { return area_[static_cast<std::size_t>(column)]; }
  double cover(int column) const { return cover_[static_cast<std::size_t>(column)]; }

 private:
  void add_segment_pieces(double x0, double y0, double x1, double y1, double dy_dx);
  void add_piece(int column, double xa, double ya, double xb, double yb);
  void touch(int first, int last) noexcept {
    first_[ranges_] = std::min(first_[ranges_], first);
    last_[ranges_] = std::max(last_[ranges_], last);
  }

  static constexpr int max_segments = 4;  // a triangle's row holds at most three
  int width_ = 0;
  int ranges_ = 0;  // segments added since start_row, each with the columns it touched
  std::array<int, max_segments> first_{}, last_{};
  std::vector<double> area_;
  std::vector<double> cover_;
};

/// Adds the parts of a counter-clockwise triangle's three edges that lie in pixel row `row` (the
/// band row - 1/2 <= y <= row + 1/2) to the row's cells.
void add_edges_in_row(RowCells& cells, const Triangle& counter_clockwise, int row);

/// Step 4 · adds the triangle's coverage of every canvas pixel it reaches: for each pixel row,
/// the three edges' parts go into the row's cells, then one sum along the row. Agrees with step
/// 1's exact area to about 1e-12; a zero-area or non-finite triangle adds nothing.
void draw_triangle_area(CoverageCanvas& canvas, const Triangle& triangle, RowCells& cells,
                        Blend blend = Blend::sum);

/// Step 5 · the same coverage composited over the canvas as alpha, one triangle after another,
/// as a 2-D library does when it draws a mesh's triangles one by one with anti-aliasing on.
void draw_triangle_area_over(CoverageCanvas& canvas, const Triangle& triangle, RowCells& cells);

}  // namespace tri::ch10
