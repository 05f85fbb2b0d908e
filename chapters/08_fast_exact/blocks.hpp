/// @file
/// Step 4 · block-level accept/reject: the candidate pixels cut into 8x8 blocks, each decided
/// from its corners as a whole (fully outside: skipped; fully inside: filled) and only the rest
/// tested pixel by pixel.
#pragma once

#include <algorithm>
#include <cstdint>
#include <optional>

#include "chapters/07_exact_coverage/fixed_point.hpp"
#include "chapters/08_fast_exact/incremental.hpp"
#include "chapters/08_fast_exact/pixel_writers.hpp"
#include "chapters/08_fast_exact/triangle_setup.hpp"
#include "common/canvas.hpp"
#include "common/color.hpp"
#include "common/triangle_algorithm.hpp"

namespace tri::ch08 {

/// Side of a block in pixels.
inline constexpr int block_size = 8;

/// What a block of pixels is, as far as the triangle is concerned.
enum class BlockCoverage {
  outside,  ///< one edge fails on every pixel of the block: nothing to draw
  inside,   ///< every edge passes on every pixel: fill it without testing
  partial,  ///< neither: test its pixels
};

// [listing classify_block]
/// Classifies a rectangle of pixels within the setup's range. An edge value is linear in x and y,
/// so over a rectangle it is smallest and largest at two of its corners, which the step signs
/// name: exact integers, so "inside" and "outside" are never wrong, only "partial" is cautious
/// (e.g. a block beyond a vertex that no single edge rejects).
inline BlockCoverage classify_block(const TriangleSetup& setup,
                                    const ch05::PixelBox& block) noexcept {
  const std::int64_t dx = block.min.x - setup.range.min.x;
  const std::int64_t dy = block.min.y - setup.range.min.y;
  const std::int64_t width = block.max.x - block.min.x;
  const std::int64_t height = block.max.y - block.min.y;
  bool inside = true;
  for (const EdgeFunction& edge : setup.edges) {
    const std::int64_t corner = edge.at(dx, dy);
    const std::int64_t across = edge.step_x * width, up = edge.step_y * height;
    const std::int64_t largest =
        corner + std::max<std::int64_t>(across, 0) + std::max<std::int64_t>(up, 0);
    if (largest < 0) return BlockCoverage::outside;
    const std::int64_t smallest =
        corner + std::min<std::int64_t>(across, 0) + std::min<std::int64_t>(up, 0);
    inside = inside && smallest >= 0;
  }
  return inside ? BlockCoverage::inside : BlockCoverage::partial;
}
// [/listing]

/// Calls visit(block, coverage) for each block_size x block_size block of the setup's range (the
/// last column and row of blocks clipped to the range), row of blocks by row of blocks from the
/// bottom. Blocks start at the range's first pixel, so a triangle smaller than a block is one.
template <class Visit>
void for_each_block(const TriangleSetup& setup, Visit&& visit) {
  const ch05::PixelBox& r = setup.range;
  for (int y = r.min.y; y <= r.max.y; y += block_size) {
    const int last_y = y + block_size - 1 < r.max.y ? y + block_size - 1 : r.max.y;
    for (int x = r.min.x; x <= r.max.x; x += block_size) {
      const int last_x = x + block_size - 1 < r.max.x ? x + block_size - 1 : r.max.x;
      const ch05::PixelBox block{{x, y}, {last_x, last_y}};
      visit(block, classify_block(setup, block));
    }
  }
}

// [listing for_each_block_run]
/// for_each_block for drawing: each run of consecutive inside blocks of a row of blocks is handed
/// over as one rectangle, fill_run(rectangle), so it is filled with long spans rather than block
/// by block; each partial block goes to test_block(block); outside blocks to nobody.
template <class FillRun, class TestBlock>
void for_each_block_run(const TriangleSetup& setup, FillRun&& fill_run, TestBlock&& test_block) {
  std::optional<ch05::PixelBox> run;  // the inside blocks met since the last other block
  const auto end_run = [&] {
    if (run) fill_run(*run);
    run.reset();
  };
  for_each_block(setup, [&](const ch05::PixelBox& block, BlockCoverage coverage) {
    if (run && run->min.y != block.min.y) end_run();  // a new row of blocks
    if (coverage == BlockCoverage::inside) {
      if (run) {
        run->max.x = block.max.x;
      } else {
        run = block;
      }
      return;
    }
    end_run();
    if (coverage == BlockCoverage::partial) test_block(block);
  });
  end_run();
}
// [/listing]

/// The pixels of a partial block, each tested with step 2's one-branch test on step 1's
/// incrementally updated edge values; writer.pixel(x, y) for the covered ones.
template <PixelWriter Writer>
void fill_block_pixels(const TriangleSetup& setup, const ch05::PixelBox& block, Writer& writer) {
  walk_incremental(setup, block,
                   [&](int x, int y, std::int64_t w0, std::int64_t w1, std::int64_t w2) {
                     if (inside_all_edges(w0, w1, w2)) writer.pixel(x, y);
                   });
}

/// Step 4 · 8x8 blocks: skip the outside ones, fill runs of inside ones span by span, and test
/// the pixels of the partial ones with step 2's incremental one-branch test. Its canvas entries,
/// compiled in blocks.cpp: draw_triangle_blocks_8x8, and OnCanvas' draw_rows for bands of rows.
void fill_blocks_8x8(const TriangleSetup& setup, CanvasWriter writer);
extern template struct OnCanvas<fill_blocks_8x8>;
inline constexpr DrawTriangleFunction draw_triangle_blocks_8x8 = OnCanvas<fill_blocks_8x8>::draw;

}  // namespace tri::ch08
