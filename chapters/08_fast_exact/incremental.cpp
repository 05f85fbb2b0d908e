#include "chapters/08_fast_exact/incremental.hpp"

namespace tri::ch08 {

// [listing draw_triangle_incremental]
void draw_triangle_incremental(Canvas& canvas, const Triangle& triangle, Color color) {
  const auto setup = setup_triangle(triangle, canvas.width(), canvas.height());
  if (!setup) return;
  walk_incremental(*setup, [&](int x, int y, std::int64_t w0, std::int64_t w1, std::int64_t w2) {
    if (w0 >= 0 && w1 >= 0 && w2 >= 0) canvas.put_pixel(x, y, color);
  });
}
// [/listing]

// [listing draw_triangle_all_edges]
void draw_triangle_all_edges(Canvas& canvas, const Triangle& triangle, Color color) {
  const auto setup = setup_triangle(triangle, canvas.width(), canvas.height());
  if (!setup) return;
  walk_incremental(*setup, [&](int x, int y, std::int64_t w0, std::int64_t w1, std::int64_t w2) {
    if (inside_all_edges(w0, w1, w2)) canvas.put_pixel(x, y, color);
  });
}
// [/listing]

}  // namespace tri::ch08
