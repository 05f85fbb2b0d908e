#include "chapters/04_scanline/lower_half.hpp"

#include "chapters/04_scanline/clip.hpp"
#include "common/pixel_diagram.hpp"

namespace tri::ch04 {

// [listing lower_half_ends]
SpanEnds lower_half_ends(const SortedTriangle& t, std::int64_t y) noexcept {
  const std::int64_t total_height = static_cast<std::int64_t>(t.p2.y) - t.p0.y;
  const std::int64_t segment_height = static_cast<std::int64_t>(t.p1.y) - t.p0.y + 1;
  const std::int64_t i = y - t.p0.y;
  return {truncated_boundary_x(t.p0, t.p2, i, total_height),
          truncated_boundary_x(t.p0, t.p1, i, segment_height)};
}
// [/listing]

// [listing draw_lower_half_boundary_points]
void draw_lower_half_boundary_points(Canvas& canvas, glm::ivec2 a, glm::ivec2 b, glm::ivec2 c) {
  const SortedTriangle t = sort_by_y(a, b, c);
  if (t.p0.y == t.p2.y) return;  // all on one row: the total height would divide 0 by 0
  const RowsOnCanvas rows = rows_on_canvas(canvas, t.p0.y, t.p1.y);
  for (std::int64_t y = rows.first; y <= rows.last; ++y) {
    const SpanEnds ends = lower_half_ends(t, y);
    put_pixel_if_on_canvas(canvas, ends.a, y, diagram_colors::vermillion);
    put_pixel_if_on_canvas(canvas, ends.b, y, diagram_colors::blue);
  }
}
// [/listing]

// [listing fill_lower_half]
void fill_half(Canvas& canvas, const SortedTriangle& t, std::int64_t low, std::int64_t high,
               HalfEnds ends, Color color) {
  const RowsOnCanvas rows = rows_on_canvas(canvas, low, high);
  for (std::int64_t y = rows.first; y <= rows.last; ++y) {
    const SpanEnds span = ends(t, y);
    fill_span_between(canvas, y, span.a, span.b, color);
  }
}

void fill_lower_half(Canvas& canvas, glm::ivec2 a, glm::ivec2 b, glm::ivec2 c, Color color) {
  const SortedTriangle t = sort_by_y(a, b, c);
  if (t.p0.y == t.p2.y) return;  // all on one row: the total height would divide 0 by 0
  fill_half(canvas, t, t.p0.y, t.p1.y, lower_half_ends, color);
}
// [/listing]

}  // namespace tri::ch04
