#include "chapters/08_fast_exact/hybrid.hpp"

#include "chapters/08_fast_exact/simd.hpp"
#include "chapters/08_fast_exact/spans.hpp"

namespace tri::ch08 {

// [listing choose_per_triangle]
template <PixelWriter Writer>
void fill_hybrid(const TriangleSetup& setup, Writer& writer) {
  if (fits_one_block(setup)) {
    fill_simd(setup, writer);
  } else {
    fill_spans(setup, writer);
  }
}

namespace {

template <PixelWriter Writer>
void draw_batch_with(Canvas& canvas, std::span<const SceneTriangle> triangles) {
  for (const SceneTriangle& triangle : triangles) {
    const auto setup = setup_triangle(triangle.vertices, canvas.width(), canvas.height());
    if (!setup) continue;
    Writer writer(canvas, triangle.color);
    fill_hybrid(*setup, writer);
  }
}
// [/listing]

}  // namespace

template void fill_hybrid(const TriangleSetup&, RowWriter&);
template void fill_hybrid(const TriangleSetup&, CountingWriter&);

void draw_triangle_hybrid(Canvas& canvas, const Triangle& triangle, Color color) {
  set_up_and_fill(canvas, triangle, color,
                  [](const TriangleSetup& setup, auto& writer) { fill_hybrid(setup, writer); });
}

void draw_triangle_hybrid_rows(Canvas& canvas, const Triangle& triangle, Color color, int first_row,
                               int last_row) {
  set_up_and_fill_rows(
      canvas, triangle, color, first_row, last_row,
      [](const TriangleSetup& setup, auto& writer) { fill_hybrid(setup, writer); });
}

void draw_batch_hybrid(Canvas& canvas, std::span<const SceneTriangle> triangles) {
  with_writer_type(canvas, [&]<class Writer>() { draw_batch_with<Writer>(canvas, triangles); });
}

}  // namespace tri::ch08
