#include "chapters/08_fast_exact/narrow_canvases.hpp"

#include "chapters/08_fast_exact/simd.hpp"
#include "chapters/08_fast_exact/spans.hpp"
#include "chapters/08_fast_exact/triangle_setup.hpp"

// The block's lanes are 32 bytes wide and passed by value between always-inlined functions, in
// the AVX2 copy too: GCC's note (-Wpsabi) about such calls concerns no call that exists.
#pragma GCC diagnostic ignored "-Wpsabi"

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

namespace {

using BlockLanes = Vector<std::int32_t, 8>;  // the eight pixels of one row of the block

// The OR of the eight lanes, whose bits are disjoint: halves folded onto each other.
[[gnu::always_inline]] inline std::uint32_t or_of_lanes(BlockLanes v) noexcept {
  using Half = Vector<std::int32_t, 4>;
  using Quarter = Vector<std::int32_t, 2>;
  const Half half =
      __builtin_shufflevector(v, v, 0, 1, 2, 3) | __builtin_shufflevector(v, v, 4, 5, 6, 7);
  const Quarter quarter =
      __builtin_shufflevector(half, half, 0, 1) | __builtin_shufflevector(half, half, 2, 3);
  return static_cast<std::uint32_t>(quarter[0] | quarter[1]);
}

template <InstructionSet Set>
struct MaskBlock {
  [[gnu::always_inline]] static void run(MaskCanvas& canvas, const TriangleSetup& setup) noexcept {
    // Edge e at the block's pixel (x, y): lane x of w[e] on row y. Like step 5's lane test, the
    // products step_x * x go through floats (SSE2 has no 32-bit multiply): |step_x| <= 2^18 with
    // 32-bit lanes, so step_x * 7 < 2^21 is exact.
    const Vector<float, 8> column{0, 1, 2, 3, 4, 5, 6, 7};
    BlockLanes w[3];
    std::int32_t up[3];
    for (std::size_t e = 0; e < 3; ++e) {
      const EdgeFunction& edge = setup.edges[e];
      w[e] = static_cast<std::int32_t>(edge.value) +
             __builtin_convertvector(column * static_cast<float>(edge.step_x), BlockLanes);
      up[e] = static_cast<std::int32_t>(edge.step_y);
    }
    // Row y's covered pixels become bits 8y + x: rows 0 to 3 in `low`, rows 4 to 7 in `high`.
    // All eight rows, without a branch; rows and columns beyond the range are masked out below.
    const BlockLanes first_bits{1, 2, 4, 8, 16, 32, 64, 128};
    BlockLanes low{}, high{};
    for (int y = 0; y < 8; ++y) {
      const BlockLanes covered = (w[0] | w[1] | w[2]) >= 0;  // all ones where every edge is >= 0
      const BlockLanes bits = first_bits << (8 * (y % 4));
      if (y < 4) {
        low |= covered & bits;
      } else {
        high |= covered & bits;
      }
      for (std::size_t e = 0; e < 3; ++e) w[e] += up[e];
    }
    const ch05::PixelBox& range = setup.range;
    const auto columns = static_cast<unsigned>(range.max.x - range.min.x);  // 0 to 7
    const auto rows = static_cast<unsigned>(range.max.y - range.min.y);
    const std::uint64_t in_range =
        ((0xFFu >> (7 - columns)) * 0x0101010101010101u) & (~std::uint64_t{0} >> (8 * (7 - rows)));
    const std::uint64_t pixels =
        (or_of_lanes(low) | std::uint64_t{or_of_lanes(high)} << 32) & in_range;
    // Each row's byte goes into its word at the range's first pixel, and its top bits into the
    // next word when the range crosses into it.
    const auto x = static_cast<unsigned>(range.min.x);
    const unsigned shift = x % 64;
    const bool crosses = static_cast<unsigned>(range.max.x) / 64 != x / 64;
    std::uint64_t* words = canvas.row(range.min.y) + x / 64;
    for (unsigned y = 0; y <= rows; ++y, words += canvas.words_per_row()) {
      const std::uint64_t row = (pixels >> (8 * y)) & 0xFF;
      words[0] |= row << shift;
      if (crosses) words[1] |= row >> (64 - shift);
    }
  }
};

}  // namespace

bool fits_mask_block(const TriangleSetup& setup) noexcept {
  return fits_one_block(setup) && fits_32_bit_lanes(setup);
}

void fill_mask_block(MaskCanvas& canvas, const TriangleSetup& setup, InstructionSet set) noexcept {
  copy_for<MaskBlock>(set)(canvas, setup);
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
