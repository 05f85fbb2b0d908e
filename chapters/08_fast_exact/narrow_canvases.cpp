#include "chapters/08_fast_exact/narrow_canvases.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "chapters/08_fast_exact/instruction_sets.hpp"
#include "chapters/08_fast_exact/spans.hpp"
#include "chapters/08_fast_exact/triangle_setup.hpp"

// The mask's lanes are 32 bytes wide and passed by value between always-inlined functions, in
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

using EightLanes = Vector<std::int32_t, 8>;

// Sets pixel x + i of a mask row's words where bit i of `bits` is set, with one 8-byte load, OR
// and store, no branch on where the words end. Precondition: mask_window_stores; x >= 0; bit i
// is set only for i < 57 and x + i < 64 * words_per_row.
[[gnu::always_inline]] inline void or_mask_bits_at(std::uint64_t* words, int words_per_row, int x,
                                                   std::uint64_t bits) noexcept {
  const auto first = static_cast<unsigned>(x);
  const unsigned byte = std::min(first / 8, static_cast<unsigned>(words_per_row) * 8 - 8);
  unsigned char* window = reinterpret_cast<unsigned char*>(words) + byte;
  std::uint64_t old;
  std::memcpy(&old, window, sizeof old);
  old |= bits << (first - 8 * byte);
  std::memcpy(window, &old, sizeof old);
}

// The OR of eight lanes whose bits are disjoint: halves folded onto each other.
[[gnu::always_inline]] inline std::uint32_t or_of_lanes(EightLanes v) noexcept {
  using Half = Vector<std::int32_t, 4>;
  using Quarter = Vector<std::int32_t, 2>;
  const Half half =
      __builtin_shufflevector(v, v, 0, 1, 2, 3) | __builtin_shufflevector(v, v, 4, 5, 6, 7);
  const Quarter quarter =
      __builtin_shufflevector(half, half, 0, 1) | __builtin_shufflevector(half, half, 2, 3);
  return static_cast<std::uint32_t>(quarter[0] | quarter[1]);
}

// fill_mask_lanes with 8 * Parts columns from the range's first one (Parts is 1 to 4). Each
// eight are one vector of their own: GCC 12 split wider generic vectors badly.
template <int Parts>
[[gnu::always_inline]] inline void fill_lanes(MaskCanvas& canvas,
                                              const TriangleSetup& setup) noexcept {
  // Edge e at pixel 8 * p + i of the current row: lane i of w[e][p]. As in step 5's lane test,
  // the products step_x * i go through floats (SSE2 has no 32-bit multiply): with 32-bit lanes
  // |step_x| <= 2^18, so step_x * 31 < 2^23 is exact.
  const Vector<float, 8> column{0, 1, 2, 3, 4, 5, 6, 7};
  const EightLanes first_bits{1, 2, 4, 8, 16, 32, 64, 128};  // each eight signs become a byte
  EightLanes w[3][Parts];
  std::int32_t up[3];
  for (std::size_t e = 0; e < 3; ++e) {
    const EdgeFunction& edge = setup.edges[e];
    const auto step = static_cast<float>(edge.step_x);
    for (int p = 0; p < Parts; ++p) {
      w[e][p] = static_cast<std::int32_t>(edge.value) +
                __builtin_convertvector((column + static_cast<float>(8 * p)) * step, EightLanes);
    }
    up[e] = static_cast<std::int32_t>(edge.step_y);
  }
  // Locals, since the stores go through bytes, which may alias anything the loop reads.
  const int x = setup.range.min.x, last_y = setup.range.max.y;
  const std::uint64_t columns = ~std::uint64_t{0} >> (63 - (setup.range.max.x - x));
  const int words_per_row = canvas.words_per_row();
  std::uint64_t* words = canvas.row(setup.range.min.y);
  // Four rows at a time: row j's signs in byte j of 32-bit lanes, then one fold per eight lanes.
  for (int y = setup.range.min.y; y <= last_y; y += 4) {
    EightLanes rows[Parts] = {};
    for (int j = 0; j < 4; ++j) {
      for (int p = 0; p < Parts; ++p) {
        // All ones where every edge is >= 0.
        const EightLanes covered = (w[0][p] | w[1][p] | w[2][p]) >= 0;
        rows[p] |= covered & (first_bits << (8 * j));
        for (std::size_t e = 0; e < 3; ++e) w[e][p] += up[e];
      }
    }
    std::uint32_t bytes[Parts];
    for (int p = 0; p < Parts; ++p) bytes[p] = or_of_lanes(rows[p]);
    for (int j = 0; j < 4 && y + j <= last_y; ++j, words += words_per_row) {
      std::uint64_t bits = 0;
      for (int p = 0; p < Parts; ++p) {
        bits |= std::uint64_t{(bytes[p] >> (8 * j)) & 0xFFu} << (8 * p);
      }
      or_mask_bits_at(words, words_per_row, x, bits & columns);
    }
  }
}

template <InstructionSet Set>
struct MaskLanes {
  [[gnu::always_inline]] static void run(MaskCanvas& canvas, const TriangleSetup& setup) noexcept {
    const int columns = setup.range.max.x - setup.range.min.x;
    if (columns < 8) {
      fill_lanes<1>(canvas, setup);
    } else if (columns < 16) {
      fill_lanes<2>(canvas, setup);
    } else if (columns < 24) {
      fill_lanes<3>(canvas, setup);
    } else {
      fill_lanes<4>(canvas, setup);
    }
  }
};

}  // namespace

void fill_mask_lanes(MaskCanvas& canvas, const TriangleSetup& setup, InstructionSet set) noexcept {
  copy_for<MaskLanes>(set)(canvas, setup);
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
