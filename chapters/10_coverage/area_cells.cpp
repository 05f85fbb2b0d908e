#include "chapters/10_coverage/area_cells.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>

namespace tri::ch10 {
namespace {

// Pixel i spans [i - 1/2, i + 1/2): the column an x lies in.
// (std::floor is a library call on baseline x86-64; this is floor for |x| < 2^31.)
int column_of(double x) {
  const double shifted = x + 0.5;
  const auto truncated = static_cast<int>(shifted);
  return truncated > shifted ? truncated - 1 : truncated;
}

// x on the line through a at height y, for an edge whose x changes by dx_dy per unit of y.
double x_at(glm::dvec2 a, double dx_dy, double y) {
  return a.x + (y - a.y) * dx_dy;
}

}  // namespace

void RowCells::start_row(int width) {
  if (area_.size() < static_cast<std::size_t>(width) + 1) {
    area_.assign(static_cast<std::size_t>(width) + 1, 0.0);
    cover_.assign(static_cast<std::size_t>(width) + 1, 0.0);
  }
  for (int k = 0; k < ranges_; ++k) {  // cells read but not added to a canvas (figures, tests)
    std::fill(area_.begin() + first_[k], area_.begin() + last_[k] + 1, 0.0);
    std::fill(cover_.begin() + first_[k], cover_.begin() + last_[k] + 1, 0.0);
  }
  width_ = width;
  ranges_ = 0;
}

// [listing add_piece]
// A piece of an edge inside one cell: the area between it and the cell's right side goes to the
// cell, and its height to the covers of the cells to its right. Left of the canvas only the cover
// matters (it reaches column 0); right of the canvas nothing does, but the row must then be summed
// up to the canvas's last column. The touched columns bound the row's sum.
inline void RowCells::add_piece(int column, double xa, double ya, double xb, double yb) {
  const double height = yb - ya;
  if (column < 0) {
    cover_[0] += height;
    touch(0, 0);
  } else if (column < width_) {
    area_[column] += height * ((column + 0.5) - (xa + xb) / 2);
    cover_[column + 1] += height;
    touch(column, column + 1);
  } else {
    touch(width_, width_);  // nothing to add, but the row is summed to the canvas's end
  }
}
// [/listing]

void RowCells::add_segment(double x0, double y0, double x1, double y1) {
  add_segment(x0, y0, x1, y1, (y1 - y0) / (x1 - x0));
}

void RowCells::add_segment(double x0, double y0, double x1, double y1, double dy_dx) {
  first_[ranges_] = width_;  // the columns this segment touches, widened by add_piece
  last_[ranges_] = 0;
  add_segment_pieces(x0, y0, x1, y1, dy_dx);
  ++ranges_;
}

void RowCells::add_segment_pieces(double x0, double y0, double x1, double y1, double dy_dx) {
  // Clip the walk to the columns that matter: everything left of the canvas is one cover.
  const double left = -0.5, right = width_ - 0.5;
  if (x0 < left && x1 < left) return add_piece(-1, x0, y0, x1, y1);
  if (x0 >= right && x1 >= right) return add_piece(width_, x0, y0, x1, y1);
  if (x0 == x1) return add_piece(std::clamp(column_of(x0), -1, width_), x0, y0, x1, y1);
  const int step = x1 > x0 ? 1 : -1;
  int column = column_of(x0);
  if (step < 0 && x0 == column - 0.5) --column;  // leaving leftwards from a cell's left side
  int last = column_of(x1);
  if (step > 0 && x1 == last - 0.5) --last;  // arriving at a cell's left side from the left
  column = std::clamp(column, -1, width_);
  last = std::clamp(last, -1, width_);
  double xs = x0, ys = y0;
  while (column != last) {
    const double side = step > 0 ? column + 0.5 : column - 0.5;  // the side it leaves through
    const double y_side = y0 + (side - x0) * dy_dx;
    add_piece(column, xs, ys, side, y_side);
    xs = side;
    ys = y_side;
    column += step;
  }
  add_piece(column, xs, ys, x1, y1);
}

// [listing add_to_canvas]
void RowCells::add_to_canvas(CoverageCanvas& canvas, int y, Blend blend) {
  // The segments' columns from left to right (at most three segments in a triangle's row).
  std::array<int, max_segments> order{};
  for (int k = 0; k < ranges_; ++k) {  // insertion sort by first column
    int j = k;
    for (; j > 0 && first_[order[j - 1]] > first_[k]; --j) order[j] = order[j - 1];
    order[j] = k;
  }
  float* row = canvas.row(y);
  const auto sum_along_row = [&](auto&& put) {
    double cover = 0;  // the heights of the edge pieces left of the column
    int x = ranges_ > 0 ? first_[order[0]] : 0;
    for (int k = 0; k < ranges_; ++k) {
      // Between segments no cell holds anything: the cover alone, the same for every pixel.
      const auto between = static_cast<float>(-cover);
      for (; x < first_[order[k]]; ++x) put(row[x], between);
      for (; x <= std::min(last_[order[k]], width_ - 1); ++x) {
        cover += cover_[x];
        const double coverage = -(cover + area_[x]);  // a counter-clockwise outline sums to -area
        area_[x] = cover_[x] = 0;                     // ready for the next row
        if (coverage != 0) put(row[x], static_cast<float>(coverage));
      }
    }
  };
  // One pass per blend, so the loop does not decide the blend at every pixel.
  if (blend == Blend::sum) {
    sum_along_row([](float& v, float c) { v += c; });
  } else {
    sum_along_row([](float& v, float c) {
      if (c != 0) v += c * (1.0f - v);
    });
  }
  area_[width_] = cover_[width_] = 0;  // a segment right of the canvas touched only this
  ranges_ = 0;
}
// [/listing]

namespace {

// One edge of a counter-clockwise triangle, prepared once for all its rows: no division per row.
struct RowEdge {
  glm::dvec2 a;
  double low, high;     // its lowest and highest y
  double dx_dy, dy_dx;  // its slopes (dy_dx infinite for a vertical edge)
  bool upward;          // walked from low to high
};

// The triangle's edges that are not horizontal (a horizontal edge adds no height).
int row_edges(const Triangle& t, std::array<RowEdge, 3>& edges) {
  int count = 0;
  for (int k = 0; k < 3; ++k) {
    const glm::dvec2 a = t[k], b = t[(k + 1) % 3];
    if (a.y == b.y) continue;
    edges[count++] = {a,
                      std::min(a.y, b.y),
                      std::max(a.y, b.y),
                      (b.x - a.x) / (b.y - a.y),
                      (b.y - a.y) / (b.x - a.x),
                      a.y < b.y};
  }
  return count;
}

// [listing add_edges_in_row]
void add_edges_in_row(RowCells& cells, std::span<const RowEdge> edges, int row) {
  for (const RowEdge& e : edges) {
    const double low = std::max(e.low, row - 0.5), high = std::min(e.high, row + 0.5);
    if (low >= high) continue;
    // The edge's part in this row, walked in the edge's own direction.
    const double y0 = e.upward ? low : high, y1 = e.upward ? high : low;
    cells.add_segment(x_at(e.a, e.dx_dy, y0), y0, x_at(e.a, e.dx_dy, y1), y1, e.dy_dx);
  }
}
// [/listing]

}  // namespace

void add_edges_in_row(RowCells& cells, const Triangle& counter_clockwise, int row) {
  std::array<RowEdge, 3> edges;
  const int count = row_edges(counter_clockwise, edges);
  add_edges_in_row(cells, std::span(edges).first(static_cast<std::size_t>(count)), row);
}

// [listing draw_triangle_area]
void draw_triangle_area(CoverageCanvas& canvas, const Triangle& triangle, RowCells& cells,
                        Blend blend) {
  Triangle t = triangle;
  const double doubled =
      (t[1].x - t[0].x) * (t[2].y - t[0].y) - (t[2].x - t[0].x) * (t[1].y - t[0].y);
  if (!std::isfinite(doubled) || doubled == 0) return;
  if (doubled < 0) std::swap(t[1], t[2]);  // counter-clockwise, so every area has one sign
  std::array<RowEdge, 3> edges;
  const auto prepared = std::span(edges).first(static_cast<std::size_t>(row_edges(t, edges)));
  const auto [low_y, high_y] = std::minmax({t[0].y, t[1].y, t[2].y});
  const int first_row = std::max(0, column_of(low_y));
  const int last_row = std::min(canvas.height() - 1, column_of(high_y));
  for (int row = first_row; row <= last_row; ++row) {
    cells.start_row(canvas.width());
    add_edges_in_row(cells, prepared, row);
    cells.add_to_canvas(canvas, row, blend);
  }
}
// [/listing]

void draw_triangle_area_over(CoverageCanvas& canvas, const Triangle& triangle, RowCells& cells) {
  draw_triangle_area(canvas, triangle, cells, Blend::over);
}

}  // namespace tri::ch10
