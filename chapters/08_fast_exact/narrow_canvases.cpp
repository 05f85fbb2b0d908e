#include "chapters/08_fast_exact/narrow_canvases.hpp"

#include "chapters/08_fast_exact/spans.hpp"
#include "chapters/08_fast_exact/triangle_setup.hpp"

namespace tri::ch08 {

IndexCanvas::IndexCanvas(int width, int height)
    : width_(width),
      height_(height),
      bytes_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0) {}

MaskCanvas::MaskCanvas(int width, int height)
    : width_(width),
      height_(height),
      words_per_row_((width + 63) / 64),
      words_(static_cast<std::size_t>(words_per_row_) * static_cast<std::size_t>(height), 0) {}

namespace {

// fill_spans over the triangle's setup clipped to rows first_row..last_row of the canvas.
template <class NarrowCanvas, class Writer>
void fill_rows(NarrowCanvas& canvas, const Triangle& triangle, int first_row, int last_row,
               Writer writer) {
  const auto setup = setup_triangle(triangle, canvas.width(), canvas.height());
  if (!setup) return;
  const auto part = clip_setup(*setup, {{0, first_row}, {canvas.width() - 1, last_row}});
  if (part) fill_spans(*part, writer);
}

}  // namespace

void draw_triangle_spans_index8(IndexCanvas& canvas, const Triangle& triangle, std::uint8_t index) {
  const auto setup = setup_triangle(triangle, canvas.width(), canvas.height());
  if (!setup) return;
  IndexWriter writer(canvas, index);
  fill_spans(*setup, writer);
}

void draw_triangle_spans_mask1(MaskCanvas& canvas, const Triangle& triangle) {
  const auto setup = setup_triangle(triangle, canvas.width(), canvas.height());
  if (!setup) return;
  MaskWriter writer(canvas);
  fill_spans(*setup, writer);
}

void draw_narrow_spans(NarrowTarget& target, std::span<const SceneTriangle> triangles) {
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    const auto setup = setup_triangle(triangles[i].vertices, target.width(), target.height());
    if (setup) target.with_writer(i, [&](auto& writer) { fill_spans(*setup, writer); });
  }
}

void draw_triangle_spans_index8_rows(IndexCanvas& canvas, const Triangle& triangle,
                                     std::uint8_t index, int first_row, int last_row) {
  fill_rows(canvas, triangle, first_row, last_row, IndexWriter(canvas, index));
}

void draw_triangle_spans_mask1_rows(MaskCanvas& canvas, const Triangle& triangle, int first_row,
                                    int last_row) {
  fill_rows(canvas, triangle, first_row, last_row, MaskWriter(canvas));
}

}  // namespace tri::ch08
