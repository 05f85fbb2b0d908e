#include "chapters/04_scanline/scanline_fills.hpp"

#include "chapters/04_scanline/clip.hpp"

namespace tri::ch04 {
namespace {

// [listing fill_single_loop_rows]
// The single loop over rows t0.y .. t0.y + last_i, shared by the fixed and the published bound.
void fill_single_loop_rows(Canvas& canvas, const SortedTriangle& t, std::int64_t last_i,
                           Color color) {
  const RowsOnCanvas rows = rows_on_canvas(canvas, t.p0.y, t.p0.y + last_i);
  for (std::int64_t y = rows.first; y <= rows.last; ++y) {
    const SpanEnds ends = single_loop_ends(t, y - t.p0.y);
    fill_span_between(canvas, y, ends.a, ends.b, color);
  }
}
// [/listing]

}  // namespace

// [listing upper_half_ends]
SpanEnds upper_half_ends(const SortedTriangle& t, std::int64_t y) noexcept {
  const std::int64_t total_height = static_cast<std::int64_t>(t.p2.y) - t.p0.y;
  const std::int64_t segment_height = static_cast<std::int64_t>(t.p2.y) - t.p1.y + 1;
  return {truncated_boundary_x(t.p0, t.p2, y - t.p0.y, total_height),
          truncated_boundary_x(t.p1, t.p2, y - t.p1.y, segment_height)};
}
// [/listing]

// [listing fill_two_loops]
void fill_two_loops(Canvas& canvas, glm::ivec2 a, glm::ivec2 b, glm::ivec2 c, Color color) {
  const SortedTriangle t = sort_by_y(a, b, c);
  if (t.p0.y == t.p2.y) return;  // all on one row: the total height would divide 0 by 0
  fill_half(canvas, t, t.p0.y, t.p1.y, lower_half_ends, color);  // step 4's loop
  fill_half(canvas, t, t.p1.y, t.p2.y, upper_half_ends, color);  // row t1.y again, up to t2.y
}
// [/listing]

// [listing single_loop_ends]
SpanEnds single_loop_ends(const SortedTriangle& t, std::int64_t i) noexcept {
  const std::int64_t total_height = static_cast<std::int64_t>(t.p2.y) - t.p0.y;
  const std::int64_t lower_height = static_cast<std::int64_t>(t.p1.y) - t.p0.y;
  const bool second_half = i > lower_height || lower_height == 0;
  const std::int64_t b =
      second_half ? truncated_boundary_x(t.p1, t.p2, i - lower_height, total_height - lower_height)
                  : truncated_boundary_x(t.p0, t.p1, i, lower_height);
  return {truncated_boundary_x(t.p0, t.p2, i, total_height), b};
}
// [/listing]

// [listing single_loop_bounds]
void fill_single_loop(Canvas& canvas, glm::ivec2 a, glm::ivec2 b, glm::ivec2 c, Color color) {
  const SortedTriangle t = sort_by_y(a, b, c);
  if (t.p0.y == t.p2.y) return;  // the article's early return for a triangle on one row
  fill_single_loop_rows(canvas, t, static_cast<std::int64_t>(t.p2.y) - t.p0.y, color);
}

void fill_single_loop_as_published(Canvas& canvas, glm::ivec2 a, glm::ivec2 b, glm::ivec2 c,
                                   Color color) {
  const SortedTriangle t = sort_by_y(a, b, c);
  if (t.p0.y == t.p2.y) return;
  // i < total height: one row short of t2.
  fill_single_loop_rows(canvas, t, static_cast<std::int64_t>(t.p2.y) - t.p0.y - 1, color);
}
// [/listing]

}  // namespace tri::ch04
