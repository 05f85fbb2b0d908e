#include "chapters/08_fast_exact/simd.hpp"

#include <cstdint>
#include <cstring>

#include "chapters/08_fast_exact/blocks.hpp"
#include "chapters/08_fast_exact/instruction_sets.hpp"

namespace tri::ch08 {
namespace {

// Lanes as generic vectors (instruction_sets.hpp): plain std::array loops were vectorized by
// GCC 12 at -O2 but not at -O3 (README, step 5).

// [listing lane_test]
// N neighbouring pixels of a row at once. Per triangle: lane i of offset[e] is edge e's change
// over i pixels; lane i of index is i.
template <class Lane, int N>
struct LaneTest {
  Vector<Lane, N> index;
  Vector<Lane, N> offset[3];

  explicit LaneTest(const TriangleSetup& setup) noexcept {
    Vector<float, N> lane_numbers;
    for (int i = 0; i < N; ++i) {
      index[i] = static_cast<Lane>(i);
      lane_numbers[i] = static_cast<float>(i);
    }
    for (int e = 0; e < 3; ++e) {
      const std::int64_t step = setup.edges[e].step_x;
      if constexpr (sizeof(Lane) == 4) {
        // SSE2 has no 32-bit integer multiply, but a float one. With 32-bit lanes |step| <= 2^18
        // (fits_32_bit_lanes), so every step * i below 2^21 is exact in a float's 24 bits.
        offset[e] =
            __builtin_convertvector(lane_numbers * static_cast<float>(step), Vector<Lane, N>);
      } else {
        offset[e] = step * index;
      }
    }
  }

  // Lane i >= 0 exactly when pixel x + i is covered and at most pixels_left pixels to the right
  // of x, from the three edge values at pixel x.
  void test(Lane w0, Lane w1, Lane w2, Lane pixels_left, Vector<Lane, N>& result) const noexcept {
    result = (w0 + offset[0]) | (w1 + offset[1]) | (w2 + offset[2]) | (pixels_left - index);
  }
};
// [/listing]

// The N pixels from `pixels` take `word` where the lane is >= 0 and keep their colour
// elsewhere: one load, a select by the lanes' sign bits, one store.
template <class Lane, int N>
void blend(Color* pixels, const Vector<Lane, N>& lanes, const Vector<std::uint32_t, N>& word) {
  using Words = Vector<std::uint32_t, N>;
  constexpr int sign_shift = 8 * sizeof(Lane) - 1;
  const Words keep = __builtin_convertvector(lanes >> sign_shift, Words);  // all ones if < 0
  Words old;
  std::memcpy(&old, pixels, sizeof(old));
  const Words blended = (old & keep) | (word & ~keep);
  std::memcpy(pixels, &blended, sizeof(blended));
}

// The edge values at the block's first pixel, in lanes.
template <class Lane>
std::array<Lane, 3> block_origin_values(const TriangleSetup& setup, const ch05::PixelBox& block) {
  const std::int64_t dx = block.min.x - setup.range.min.x;
  const std::int64_t dy = block.min.y - setup.range.min.y;
  return {static_cast<Lane>(setup.edges[0].at(dx, dy)),
          static_cast<Lane>(setup.edges[1].at(dx, dy)),
          static_cast<Lane>(setup.edges[2].at(dx, dy))};
}

// A partial block (at most N pixels wide) written straight into the rows. Everything the loop
// reads is a local copy, so the compiler keeps it in registers: pixel stores cannot alias a local.
template <class Lane, int N>
void fill_partial_block(const TriangleSetup& setup, const LaneTest<Lane, N>& lanes,
                        const ch05::PixelBox& block, RowWriter& writer) {
  const LaneTest<Lane, N> local = lanes;
  auto [w0, w1, w2] = block_origin_values<Lane>(setup, block);
  const auto s0 = static_cast<Lane>(setup.edges[0].step_y);
  const auto s1 = static_cast<Lane>(setup.edges[1].step_y);
  const auto s2 = static_cast<Lane>(setup.edges[2].step_y);
  const auto pixels_left = static_cast<Lane>(setup.range.max.x - block.min.x);
  const auto word = Vector<std::uint32_t, N>{} + writer.word();
  const std::ptrdiff_t stride = writer.stride();
  Color* row = writer.row_pixels(block.min.y) + block.min.x;
  Vector<Lane, N> covered;
  for (int rows = block.max.y - block.min.y + 1; rows > 0; --rows, row += stride) {
    local.test(w0, w1, w2, pixels_left, covered);
    blend<Lane, N>(row, covered, word);
    w0 += s0;
    w1 += s1;
    w2 += s2;
  }
}

// The same decisions through the counting writer, lane by lane.
template <class Lane, int N>
void fill_partial_block(const TriangleSetup& setup, const LaneTest<Lane, N>& lanes,
                        const ch05::PixelBox& block, CountingWriter& writer) {
  auto [w0, w1, w2] = block_origin_values<Lane>(setup, block);
  const auto pixels_left = static_cast<Lane>(setup.range.max.x - block.min.x);
  Vector<Lane, N> covered;
  for (int y = block.min.y; y <= block.max.y; ++y) {
    lanes.test(w0, w1, w2, pixels_left, covered);
    for (int i = 0; i < N; ++i) {
      if (covered[i] >= 0) writer.pixel(block.min.x + i, y);
    }
    w0 += static_cast<Lane>(setup.edges[0].step_y);
    w1 += static_cast<Lane>(setup.edges[1].step_y);
    w2 += static_cast<Lane>(setup.edges[2].step_y);
  }
}

// A triangle within one block: its rows at once in N lanes (N = 4 for ranges up to 4 pixels
// wide: one SSE2 register per operation instead of two), without classifying it.
template <class Lane, int N, class Writer>
void fill_one_block(const TriangleSetup& setup, Writer& writer) {
  if (setup.range.min.x + N <= writer.width()) {
    fill_partial_block(setup, LaneTest<Lane, N>(setup), setup.range, writer);
  } else {
    fill_block_pixels(setup, setup.range, writer);  // lanes would leave the canvas
  }
}

template <class Lane, class Writer>
void fill_blocks_simd(const TriangleSetup& setup, Writer& writer) {
  if (fits_one_block(setup)) {
    if (setup.range.max.x - setup.range.min.x < 4) {
      fill_one_block<Lane, 4>(setup, writer);
    } else {
      fill_one_block<Lane, 8>(setup, writer);
    }
    return;
  }
  const LaneTest<Lane, 8> lanes(setup);
  const int row_end = writer.width();
  for_each_block_run(
      setup,
      [&](const ch05::PixelBox& run) {
        for (int y = run.min.y; y <= run.max.y; ++y) writer.span(y, run.min.x, run.max.x + 1);
      },
      [&](const ch05::PixelBox& block) {
        // Eight lanes must stay within the writer's rows (the canvas, or a tile); a block at
        // their right end goes pixel by pixel.
        if (block.min.x + 8 <= row_end) {
          fill_partial_block(setup, lanes, block, writer);
        } else {
          fill_block_pixels(setup, block, writer);
        }
      });
}

template <class Lane, int N>
std::array<bool, 8> test_lanes(const TriangleSetup& setup, int x, int y) {
  const LaneTest<Lane, N> lanes(setup);
  const std::int64_t dx = x - setup.range.min.x, dy = y - setup.range.min.y;
  Vector<Lane, N> covered;
  lanes.test(static_cast<Lane>(setup.edges[0].at(dx, dy)),
             static_cast<Lane>(setup.edges[1].at(dx, dy)),
             static_cast<Lane>(setup.edges[2].at(dx, dy)), static_cast<Lane>(setup.range.max.x - x),
             covered);
  std::array<bool, 8> result{};
  for (int i = 0; i < N; ++i) result[i] = covered[i] >= 0;
  return result;
}

}  // namespace

std::array<bool, 8> lane_test(const TriangleSetup& setup, int x, int y, LaneWidth width,
                              int lanes) {
  if (width == LaneWidth::bits32) {
    return lanes == 4 ? test_lanes<std::int32_t, 4>(setup, x, y)
                      : test_lanes<std::int32_t, 8>(setup, x, y);
  }
  return lanes == 4 ? test_lanes<std::int64_t, 4>(setup, x, y)
                    : test_lanes<std::int64_t, 8>(setup, x, y);
}

void fill_simd(const TriangleSetup& setup, CanvasWriter any_writer) {
  any_writer.visit([&](auto& writer) {
    if (fits_32_bit_lanes(setup)) {
      fill_blocks_simd<std::int32_t>(setup, writer);
    } else {
      fill_blocks_simd<std::int64_t>(setup, writer);
    }
  });
}

template struct OnCanvas<fill_simd>;

}  // namespace tri::ch08
