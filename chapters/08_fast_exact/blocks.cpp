#include "chapters/08_fast_exact/blocks.hpp"

#include <algorithm>
#include <cstdint>

#include "chapters/08_fast_exact/pixel_writers.hpp"

namespace tri::ch08 {

void fill_blocks_8x8(const TriangleSetup& setup, CanvasWriter any_writer) {
  any_writer.visit([&](auto& writer) {
    for_each_block_run(
        setup,
        [&](const ch05::PixelBox& run) {
          for (int y = run.min.y; y <= run.max.y; ++y) writer.span(y, run.min.x, run.max.x + 1);
        },
        [&](const ch05::PixelBox& block) { fill_block_pixels(setup, block, writer); });
  });
}

template struct OnCanvas<fill_blocks_8x8>;

}  // namespace tri::ch08
