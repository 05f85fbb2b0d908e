#include "chapters/08_fast_exact/hybrid.hpp"

#include "chapters/08_fast_exact/simd.hpp"
#include "chapters/08_fast_exact/spans.hpp"

namespace tri::ch08 {
namespace {

// [listing choose_per_triangle]
// With the writer's own type, so the batch loop below inlines it: a call with a RowWriter or
// CountingWriter picks this over fill_hybrid(setup, CanvasWriter), which needs a conversion.
template <PixelWriter Writer>
void fill_hybrid(const TriangleSetup& setup, Writer& writer) {
  if (fits_one_block(setup)) {
    fill_simd(setup, writer);
  } else {
    fill_spans(setup, writer);
  }
}

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

void fill_hybrid(const TriangleSetup& setup, CanvasWriter any_writer) {
  any_writer.visit([&](auto& writer) { fill_hybrid(setup, writer); });
}

template struct OnCanvas<fill_hybrid>;

void draw_batch_hybrid(Canvas& canvas, std::span<const SceneTriangle> triangles) {
  with_writer_type(canvas, [&]<class Writer>() { draw_batch_with<Writer>(canvas, triangles); });
}

}  // namespace tri::ch08
