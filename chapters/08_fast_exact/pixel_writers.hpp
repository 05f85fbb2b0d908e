/// @file
/// The two ways the fast variants put pixels on the canvas: straight into its rows (the fast
/// path), or through put_pixel when the canvas counts writes (tests and error measurement). The
/// variants decide which pixels to write once and are templated on the writer, so both paths
/// write exactly the same pixels.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <utility>
#include <variant>

#include "chapters/08_fast_exact/instruction_sets.hpp"
#include "chapters/08_fast_exact/triangle_setup.hpp"
#include "common/canvas.hpp"
#include "common/color.hpp"
#include "common/triangle_algorithm.hpp"

namespace tri::ch08 {

static_assert(sizeof(Color) == sizeof(std::uint32_t), "a pixel is one 32-bit word");

// [listing fill_pixels]
/// Fills count pixels from first with one colour word, in stores of Bytes bytes (16 or 32; P =
/// Bytes / 4 pixels each): two stores per loop step, then two that end exactly at the span's end,
/// overlapping the ones before instead of finishing pixel by pixel, with no test of what the loop
/// left. A span shorter than 2P pixels takes two overlapping stores, or goes to the next narrower
/// store, and below 4 pixels to single words. The word sits in a local vector that no store can
/// alias, so it stays in a register. Inlined always, so that a caller compiled for AVX2 (the span
/// fill's AVX2 copy) gets its 32-byte stores; without AVX2, each becomes two 16-byte stores.
template <int Bytes>
[[gnu::always_inline]] inline void fill_pixels_in(Color* first, int count,
                                                  std::uint32_t word) noexcept {
  static_assert(Bytes == 16 || Bytes == 32);
  constexpr int P = Bytes / 4;
  using Lanes = Vector<std::uint32_t, P>;
  const Lanes lanes = Lanes{} + word;
  if (count >= 2 * P) {
    for (int i = 0; i < count - 2 * P; i += 2 * P) {
      std::memcpy(first + i, &lanes, sizeof lanes);
      std::memcpy(first + i + P, &lanes, sizeof lanes);
    }
    std::memcpy(first + count - 2 * P, &lanes, sizeof lanes);
    std::memcpy(first + count - P, &lanes, sizeof lanes);
  } else if (count >= P) {
    std::memcpy(first, &lanes, sizeof lanes);
    std::memcpy(first + count - P, &lanes, sizeof lanes);
  } else if constexpr (Bytes > 16) {
    fill_pixels_in<Bytes / 2>(first, count, word);
  } else {
    for (int i = 0; i < count; ++i) std::memcpy(first + i, &word, sizeof word);
  }
}

/// fill_pixels_in with 16-byte stores, the widest every x86-64 has (SSE2): what the portable
/// build writes with outside the span fill's copies for wider registers. GCC 12 compiles std::fill
/// over Color (canvas.cpp) into one 4-byte store per pixel (see the README).
inline void fill_pixels(Color* first, int count, std::uint32_t word) noexcept {
  fill_pixels_in<16>(first, count, word);
}
// [/listing]

/// A RowWriter's rows for the span fill: each span one fill_pixels_in with stores of Bytes bytes,
/// the row's first pixel moving up by the stride, so nothing of the canvas is read again per row.
template <int Bytes>
struct PixelRows {
  Color* row;
  std::ptrdiff_t stride;
  std::uint32_t word;
  [[gnu::always_inline]] void fill(int, int x_begin, int x_end) noexcept {
    fill_pixels_in<Bytes>(row + x_begin, x_end - x_begin, word);
  }
  // After the canvas's top row, row ends one past its last pixel: a valid pointer, never used.
  [[gnu::always_inline]] void next_row() noexcept { row += stride; }
};

/// The rows of a writer that writes spans by y: each row's span through its span(), nothing to
/// move from row to row.
template <class Writer>
struct SpanRows {
  Writer& writer;
  void fill(int y, int x_begin, int x_end) noexcept { writer.span(y, x_begin, x_end); }
  void next_row() noexcept {}
};

/// Writes into Canvas::row, with no per-pixel bounds or counter checks. Callers pass only
/// pixels of the canvas. Safe for threads that write disjoint rows, or disjoint tiles when each
/// writer is given its tile's right end (`row_end`): step 5's blends read and write back whole
/// groups of pixels, and they never reach that column.
class RowWriter {
 public:
  RowWriter(Canvas& canvas, Color color) noexcept : RowWriter(canvas, color, canvas.width()) {}
  RowWriter(Canvas& canvas, Color color, int row_end) noexcept
      : canvas_(canvas),
        color_(color),
        word_(std::bit_cast<std::uint32_t>(color)),
        row_end_(row_end) {}

  /// Pixels x_begin <= x < x_end of row y.
  void span(int y, int x_begin, int x_end) noexcept {
    fill_pixels(canvas_.row(y).data() + x_begin, x_end - x_begin, word_);
  }
  void pixel(int x, int y) noexcept { canvas_.row(y)[static_cast<std::size_t>(x)] = color_; }

  /// For code that writes rows itself (step 5's blends): row y's first pixel, the pixels from
  /// one row to the next, and the colour as a 32-bit word.
  Color* row_pixels(int y) noexcept { return canvas_.row(y).data(); }
  int stride() const noexcept { return canvas_.width(); }
  std::uint32_t word() const noexcept { return word_; }
  /// No pixel at or right of this column may be touched, not even rewritten unchanged.
  int width() const noexcept { return row_end_; }
  /// The rows from y up, for the span fill's copy for Set: stores of Set's register width.
  template <InstructionSet Set>
  PixelRows<register_bytes(Set)> rows_from(int y) noexcept {
    return {row_pixels(y), stride(), word_};
  }

 private:
  Canvas& canvas_;
  Color color_;
  std::uint32_t word_;
  int row_end_;
};

/// Writes through Canvas::put_pixel so that every write is counted. Slow, and only used while the
/// canvas counts writes. Touches nothing shared between rows (put_pixel of a canvas pixel changes
/// only that pixel and its counter), so it is safe for threads that write disjoint rows.
class CountingWriter {
 public:
  CountingWriter(Canvas& canvas, Color color) noexcept
      : CountingWriter(canvas, color, canvas.width()) {}
  CountingWriter(Canvas& canvas, Color color, int row_end) noexcept
      : canvas_(canvas), color_(color), row_end_(row_end) {}

  void span(int y, int x_begin, int x_end) noexcept {
    for (int x = x_begin; x < x_end; ++x) canvas_.put_pixel(x, y, color_);
  }
  void pixel(int x, int y) noexcept { canvas_.put_pixel(x, y, color_); }
  int width() const noexcept { return row_end_; }
  template <InstructionSet>
  SpanRows<CountingWriter> rows_from(int) noexcept {
    return {*this};
  }

 private:
  Canvas& canvas_;
  Color color_;
  int row_end_;
};

// [listing pixel_writer]
/// What every traversal needs from a writer: whole spans of a row, single pixels, the end of the
/// pixels of a row it may touch (the canvas width, or a tile's right end), and the row-store hook
/// of the span fill: rows from y up, filled span by span (fill, given the row's y) and stepped
/// (next_row), in the stores of an instruction set's copy. RowWriter and CountingWriter are the
/// canvas's two; each traversal is one template over them.
template <class Writer>
concept PixelWriter = requires(Writer writer, int x, int y) {
  writer.span(y, x, x + 1);  // pixels x_begin <= x < x_end of row y
  writer.pixel(x, y);
  { writer.width() } -> std::convertible_to<int>;
  writer.template rows_from<InstructionSet::portable>(y).fill(y, x, x + 1);
  writer.template rows_from<InstructionSet::portable>(y).next_row();
};
// [/listing]

static_assert(PixelWriter<RowWriter> && PixelWriter<CountingWriter>);

/// True when a writer's row-store hook is the same in every instruction set's copy (no vector
/// stores to widen): a loop over its rows then needs only the portable copy, and no choice.
template <class Writer>
inline constexpr bool same_rows_in_every_copy = []<std::size_t... I>(std::index_sequence<I...>) {
  using Portable =
      decltype(std::declval<Writer&>().template rows_from<InstructionSet::portable>(0));
  return (std::is_same_v<Portable, decltype(std::declval<Writer&>()
                                                .template rows_from<all_instruction_sets[I]>(0))> &&
          ...);
}
(std::make_index_sequence<all_instruction_sets.size()>{});
static_assert(!same_rows_in_every_copy<RowWriter> && same_rows_in_every_copy<CountingWriter>);

/// Calls `draw.template operator()<Writer>()` with the writer type that suits the canvas (counting
/// when it counts writes), for batch loops that make a writer per triangle themselves.
template <class Draw>
void with_writer_type(const Canvas& canvas, Draw&& draw) {
  if (canvas.write_counts_enabled()) {
    draw.template operator()<CountingWriter>();
  } else {
    draw.template operator()<RowWriter>();
  }
}

/// Calls draw(writer) with the writer that suits the canvas: counting when it counts writes.
template <class Draw>
void with_writer(Canvas& canvas, Color color, Draw&& draw) {
  if (canvas.write_counts_enabled()) {
    CountingWriter writer(canvas, color);
    draw(writer);
  } else {
    RowWriter writer(canvas, color);
    draw(writer);
  }
}

/// True when Writer is one of Writers.
template <class Writer, class... Writers>
concept OneOf = (std::same_as<Writer, Writers> || ...);

/// One of the writers Writers..., whichever the caller holds: what a fill compiled in its own
/// source takes, so that this one list says which writers it is compiled for (no instantiation per
/// writer written out). visit(fill) calls fill(writer) with the writer as its own type.
template <PixelWriter... Writers>
class OneOfWriters {
 public:
  template <OneOf<Writers...> Writer>
  OneOfWriters(Writer& writer) noexcept : writer_(&writer) {}  // implicit: callers pass a writer

  template <class Fill>
  void visit(Fill&& fill) const {
    std::visit([&](auto* writer) { fill(*writer); }, writer_);
  }

 private:
  std::variant<Writers*...> writer_;
};

/// The canvas's writers, listed once.
using CanvasWriter = OneOfWriters<RowWriter, CountingWriter>;

/// A step's fill as compiled in its own source: the pixels of a prepared triangle, through either
/// canvas writer.
using CanvasFill = void (*)(const TriangleSetup& setup, CanvasWriter writer);

/// A step on the canvas, made from its fill: one triangle (draw: the setup, then the fill with the
/// writer that suits the canvas; nothing when the setup is empty) and rows first_row..last_row of
/// it (draw_rows, the registry's draw_rows entry: the setup clipped to them, so the fill writes
/// exactly the pixels of those rows that it writes unclipped). Each step compiles its own in its
/// source, where the fill is inlined into both (`extern template` in the step's header).
template <CanvasFill fill>
struct OnCanvas {
  static void draw(Canvas& canvas, const Triangle& triangle, Color color);
  static void draw_rows(Canvas& canvas, const Triangle& triangle, Color color, int first_row,
                        int last_row);
};

template <CanvasFill fill>
void OnCanvas<fill>::draw(Canvas& canvas, const Triangle& triangle, Color color) {
  const auto setup = setup_triangle(triangle, canvas.width(), canvas.height());
  if (!setup) return;
  with_writer(canvas, color, [&](auto& writer) { fill(*setup, writer); });
}

template <CanvasFill fill>
void OnCanvas<fill>::draw_rows(Canvas& canvas, const Triangle& triangle, Color color, int first_row,
                               int last_row) {
  const auto setup = setup_triangle(triangle, canvas.width(), canvas.height());
  if (!setup) return;
  const auto part = clip_setup(*setup, {{0, first_row}, {canvas.width() - 1, last_row}});
  if (!part) return;
  with_writer(canvas, color, [&](auto& writer) { fill(*part, writer); });
}

}  // namespace tri::ch08
