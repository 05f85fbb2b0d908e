#include "chapters/08_fast_exact/blocks.hpp"

#include <algorithm>
#include <cstdint>

#include "chapters/08_fast_exact/pixel_writers.hpp"

namespace tri::ch08 {

namespace {

template <PixelWriter Writer>
void fill_blocks(const TriangleSetup& setup, Writer& writer) {
  for_each_block_run(
      setup,
      [&](const ch05::PixelBox& run) {
        for (int y = run.min.y; y <= run.max.y; ++y) writer.span(y, run.min.x, run.max.x + 1);
      },
      [&](const ch05::PixelBox& block) { fill_block_pixels(setup, block, writer); });
}

}  // namespace

void draw_triangle_blocks_8x8(Canvas& canvas, const Triangle& triangle, Color color) {
  set_up_and_fill(canvas, triangle, color,
                  [](const TriangleSetup& setup, auto& writer) { fill_blocks(setup, writer); });
}

void draw_triangle_blocks_8x8_rows(Canvas& canvas, const Triangle& triangle, Color color,
                                   int first_row, int last_row) {
  set_up_and_fill_rows(
      canvas, triangle, color, first_row, last_row,
      [](const TriangleSetup& setup, auto& writer) { fill_blocks(setup, writer); });
}

}  // namespace tri::ch08
