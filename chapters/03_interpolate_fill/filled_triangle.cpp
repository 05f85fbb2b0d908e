#include "chapters/03_interpolate_fill/filled_triangle.hpp"

#include <algorithm>
#include <utility>

#include "chapters/03_interpolate_fill/fill_steps.hpp"

namespace tri::ch03 {

// [listing draw_filled_triangle]
void draw_filled_triangle(Canvas& canvas, glm::ivec2 p0, glm::ivec2 p1, glm::ivec2 p2,
                          Color color) {
  const SortedTriangle t = sort_by_y(p0, p1, p2);  // step 1
  if (t.p0.y == t.p2.y) {
    // One row: x = f(y) has a single row, and interpolate keeps only each flat edge's first end.
    const double left = std::min({t.p0.x, t.p1.x, t.p2.x});
    const double right = std::max({t.p0.x, t.p1.x, t.p2.x});
    draw_spans(canvas, t.p0.y, LeftRightXs{{left}, {right}}, color);
    return;
  }
  const RowRange rows = visible_rows(t, canvas.height());
  if (rows.empty()) return;
  EdgeXs edges = interpolate_edges(t, rows);                                            // step 2
  std::vector<double> x012 = concatenate_short_sides(std::move(edges.x01), edges.x12);  // step 3
  const LeftRightXs spans = choose_left_right(std::move(edges.x02), std::move(x012));   // step 4
  draw_spans(canvas, rows.first, spans, color);                                         // step 5
}
// [/listing]

}  // namespace tri::ch03
