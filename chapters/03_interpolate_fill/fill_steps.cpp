#include "chapters/03_interpolate_fill/fill_steps.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <utility>

#include "chapters/01_lines/interpolate.hpp"

namespace tri::ch03 {
namespace {

// x of the edge lo -> hi (lo.y <= y <= hi.y) at row y; exactly the vertex's x at either end.
double edge_x_at(glm::ivec2 lo, glm::ivec2 hi, int y) noexcept {
  if (y == lo.y) return lo.x;
  if (y == hi.y) return hi.x;
  // 64-bit differences: coordinates of ±2^30 differ by up to 2^31.
  const auto dx = static_cast<double>(static_cast<std::int64_t>(hi.x) - lo.x);
  const auto dy = static_cast<double>(static_cast<std::int64_t>(hi.y) - lo.y);
  const auto steps = static_cast<double>(static_cast<std::int64_t>(y) - lo.y);
  return lo.x + dx * steps / dy;
}

// [listing edge_xs]
// The book's Interpolate(lo.y, lo.x, hi.y, hi.x), restricted to the rows in `rows`.
std::vector<double> edge_xs(glm::ivec2 lo, glm::ivec2 hi, RowRange rows) {
  const int first = std::max(rows.first, lo.y);
  const int last = std::min(rows.last, hi.y);
  if (first > last) return {};
  return ch01::interpolate(first, edge_x_at(lo, hi, first), last, edge_x_at(lo, hi, last));
}
// [/listing]

}  // namespace

// [listing sort_by_y]
SortedTriangle sort_by_y(glm::ivec2 p0, glm::ivec2 p1, glm::ivec2 p2) noexcept {
  if (p1.y < p0.y) std::swap(p1, p0);
  if (p2.y < p0.y) std::swap(p2, p0);
  if (p2.y < p1.y) std::swap(p2, p1);
  return {p0, p1, p2};
}
// [/listing]

RowRange triangle_rows(const SortedTriangle& t) noexcept {
  return {t.p0.y, t.p2.y};
}

RowRange visible_rows(const SortedTriangle& t, int canvas_height) noexcept {
  return {std::max(t.p0.y, 0), std::min(t.p2.y, canvas_height - 1)};
}

// [listing interpolate_edges]
EdgeXs interpolate_edges(const SortedTriangle& t, RowRange rows) {
  const RowRange kept{std::max(rows.first, t.p0.y), std::min(rows.last, t.p2.y)};
  if (!kept.empty() &&
      static_cast<std::int64_t>(kept.last) - kept.first + 1 > std::int64_t{max_canvas_side}) {
    throw std::length_error("interpolate_edges: more rows than a canvas has; clip them first");
  }
  return {edge_xs(t.p0, t.p1, kept), edge_xs(t.p1, t.p2, kept), edge_xs(t.p0, t.p2, kept)};
}
// [/listing]

// [listing concatenate_short_sides]
std::vector<double> concatenate_short_sides(std::vector<double> x01,
                                            const std::vector<double>& x12) {
  // Both present means both hold row y1: keep x12's copy. Forgetting this shifts every row above.
  if (!x01.empty() && !x12.empty()) x01.pop_back();
  x01.insert(x01.end(), x12.begin(), x12.end());
  return x01;
}
// [/listing]

std::size_t middle_row_index(std::size_t rows) noexcept {
  return rows / 2;
}

// [listing choose_left_right]
LeftRightXs choose_left_right(std::vector<double> x02, std::vector<double> x012) {
  const std::size_t rows = std::min(x02.size(), x012.size());
  if (rows == 0) return {std::move(x02), std::move(x012)};
  std::size_t row = middle_row_index(rows);
  if (x02[row] == x012[row]) {
    // The middle row is the apex where both sides meet, so it cannot tell them apart.
    for (std::size_t i = 0; i < rows; ++i) {
      if (x02[i] != x012[i]) {
        row = i;
        break;
      }
    }
  }
  if (x02[row] < x012[row]) return {std::move(x02), std::move(x012)};
  return {std::move(x012), std::move(x02)};
}
// [/listing]

// [listing draw_spans]
int nearest_column(double x, int width) noexcept {
  const double column = std::floor(x + 0.5);
  if (!(column > -1.0)) return -1;  // also catches NaN
  if (!(column < width)) return width;
  return static_cast<int>(column);
}

void draw_spans(Canvas& canvas, int first_row, const LeftRightXs& spans, Color color) noexcept {
  const auto rows = static_cast<std::int64_t>(std::min(spans.x_left.size(), spans.x_right.size()));
  // Only the array entries whose row is on the canvas: i in [begin, end).
  const std::int64_t begin = std::max<std::int64_t>(0, -std::int64_t{first_row});
  const std::int64_t end = std::min<std::int64_t>(rows, std::int64_t{canvas.height()} - first_row);
  for (std::int64_t i = begin; i < end; ++i) {
    const auto index = static_cast<std::size_t>(i);
    const int left = std::max(nearest_column(spans.x_left[index], canvas.width()), 0);
    const int right =
        std::min(nearest_column(spans.x_right[index], canvas.width()), canvas.width() - 1);
    if (left <= right) canvas.fill_span(static_cast<int>(first_row + i), left, right + 1, color);
  }
}
// [/listing]

}  // namespace tri::ch03
