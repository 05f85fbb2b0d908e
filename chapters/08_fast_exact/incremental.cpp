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

// A band of rows: the setup clipped to them, walked as above.
template <class Inside>
void draw_rows_incremental(Canvas& canvas, const Triangle& triangle, Color color, int first_row,
                           int last_row, Inside inside) {
  const auto setup = setup_triangle(triangle, canvas.width(), canvas.height());
  if (!setup) return;
  const auto part = clip_setup(*setup, {{0, first_row}, {canvas.width() - 1, last_row}});
  if (!part) return;
  walk_incremental(*part, [&](int x, int y, std::int64_t w0, std::int64_t w1, std::int64_t w2) {
    if (inside(w0, w1, w2)) canvas.put_pixel(x, y, color);
  });
}

void draw_triangle_incremental_rows(Canvas& canvas, const Triangle& triangle, Color color,
                                    int first_row, int last_row) {
  draw_rows_incremental(canvas, triangle, color, first_row, last_row,
                        [](std::int64_t w0, std::int64_t w1, std::int64_t w2) {
                          return w0 >= 0 && w1 >= 0 && w2 >= 0;
                        });
}

void draw_triangle_all_edges_rows(Canvas& canvas, const Triangle& triangle, Color color,
                                  int first_row, int last_row) {
  draw_rows_incremental(canvas, triangle, color, first_row, last_row, inside_all_edges);
}

}  // namespace tri::ch08
