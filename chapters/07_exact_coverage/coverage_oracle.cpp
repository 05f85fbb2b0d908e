#include "chapters/07_exact_coverage/coverage_oracle.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "chapters/07_exact_coverage/exact_orientation.hpp"

namespace tri::ch07 {

// [listing top_left_rule]
bool is_top_left_edge(glm::dvec2 a, glm::dvec2 b) noexcept {
  const bool top = a.y == b.y && b.x < a.x;
  const bool left = b.y < a.y;
  return top || left;
}

Triangle counter_clockwise(const Triangle& triangle) noexcept {
  Triangle t = triangle;
  if (exact_orientation(t[0], t[1], t[2]) < 0) std::swap(t[1], t[2]);
  return t;
}
// [/listing]

namespace {

// [listing inside_edge]
// Covered with respect to one edge of a counter-clockwise triangle.
bool inside_edge(glm::dvec2 a, glm::dvec2 b, glm::dvec2 p) noexcept {
  const int side = exact_orientation(a, b, p);
  return side > 0 || (side == 0 && is_top_left_edge(a, b));
}

bool covers_ccw(const Triangle& t, glm::dvec2 p) noexcept {
  return inside_edge(t[0], t[1], p) && inside_edge(t[1], t[2], p) && inside_edge(t[2], t[0], p);
}
// [/listing]

}  // namespace

// [listing oracle_covers]
bool oracle_covers(const Triangle& triangle, glm::ivec2 p) noexcept {
  if (exact_orientation(triangle[0], triangle[1], triangle[2]) == 0) return false;
  return covers_ccw(counter_clockwise(triangle), glm::dvec2(p));
}
// [/listing]

void draw_triangle_oracle(Canvas& canvas, const Triangle& triangle, Color color) {
  draw_triangle_oracle_rows(canvas, triangle, color, 0, canvas.height() - 1);
}

void draw_triangle_oracle_rows(Canvas& canvas, const Triangle& triangle, Color color, int first_row,
                               int last_row) {
  if (exact_orientation(triangle[0], triangle[1], triangle[2]) == 0) return;
  const Triangle t = counter_clockwise(triangle);
  // Candidate pixels: centres within the vertices' extent, clipped to the canvas (in doubles, so
  // vertices anywhere in the double range are fine).
  const auto low = [](double a, double b, double c) { return std::ceil(std::min({a, b, c})); };
  const auto high = [](double a, double b, double c) { return std::floor(std::max({a, b, c})); };
  const double x0 = std::max(0.0, low(t[0].x, t[1].x, t[2].x));
  const double x1 = std::min(canvas.width() - 1.0, high(t[0].x, t[1].x, t[2].x));
  const double y0 = std::max(static_cast<double>(first_row), low(t[0].y, t[1].y, t[2].y));
  const double y1 = std::min(static_cast<double>(last_row), high(t[0].y, t[1].y, t[2].y));
  if (x0 > x1 || y0 > y1) return;
  for (int y = static_cast<int>(y0); y <= static_cast<int>(y1); ++y) {
    for (int x = static_cast<int>(x0); x <= static_cast<int>(x1); ++x) {
      if (covers_ccw(t, glm::dvec2(x, y))) canvas.put_pixel(x, y, color);
    }
  }
}

}  // namespace tri::ch07
