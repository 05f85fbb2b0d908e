#include "chapters/09_anti_aliasing/sample_spans.hpp"

#include "chapters/08_fast_exact/spans.hpp"
#include "chapters/08_fast_exact/triangle_setup.hpp"

namespace tri::ch09 {

// [listing draw_triangle_samples]
void draw_triangle_samples_rows(CoverageCanvas& canvas, const Triangle& triangle,
                                const SamplePattern& pattern, int first_row, int last_row) {
  const float weight = 1.0f / static_cast<float>(pattern.offsets.size());
  const ch05::PixelBox rows{{0, first_row}, {canvas.width() - 1, last_row}};
  for (const glm::ivec2 offset : pattern.offsets) {
    const glm::dvec2 o = glm::dvec2(offset) / double{sample_units};
    const Triangle moved = {{triangle[0] - o, triangle[1] - o, triangle[2] - o}};
    const auto whole = ch08::setup_triangle(moved, canvas.width(), canvas.height());
    if (!whole) continue;
    const auto setup = ch08::clip_setup(*whole, rows);
    if (!setup) continue;
    ch08::SpanWalker walker(*setup);
    for (int y = walker.first_row(); y <= walker.last_row(); ++y, walker.next_row()) {
      const ch08::RowSpan span = walker.span();
      for (int x = span.first; x <= span.last; ++x) canvas.add(x, y, weight);
    }
  }
}
// [/listing]

void draw_triangle_samples(CoverageCanvas& canvas, const Triangle& triangle,
                           const SamplePattern& pattern) {
  draw_triangle_samples_rows(canvas, triangle, pattern, 0, canvas.height() - 1);
}

}  // namespace tri::ch09
