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
#include <cstdint>
#include <cstring>

#include "chapters/08_fast_exact/triangle_setup.hpp"
#include "common/canvas.hpp"
#include "common/color.hpp"
#include "common/triangle_algorithm.hpp"

namespace tri::ch08 {

static_assert(sizeof(Color) == sizeof(std::uint32_t), "a pixel is one 32-bit word");

// [listing fill_pixels]
/// Fills count pixels from first with one colour word, 8 pixels (two 16-byte stores) at a time:
/// the last stores of a span overlap the ones before instead of finishing pixel by pixel. The
/// word sits in a local vector that no store can alias, so it stays in a register. GCC 12
/// compiles std::fill over Color (canvas.cpp) into one 4-byte store per pixel (see the README).
inline void fill_pixels(Color* first, int count, std::uint32_t word) noexcept {
  typedef std::uint32_t Four __attribute__((vector_size(16)));
  const Four four = {word, word, word, word};
  const auto store4 = [&four](Color* at) { std::memcpy(at, &four, sizeof four); };
  if (count >= 8) {
    int i = 0;
    for (; i + 8 <= count; i += 8) {
      store4(first + i);
      store4(first + i + 4);
    }
    if (i < count) {
      store4(first + count - 8);
      store4(first + count - 4);
    }
  } else if (count >= 4) {
    store4(first);
    store4(first + count - 4);
  } else {
    for (int i = 0; i < count; ++i) std::memcpy(first + i, &word, sizeof word);
  }
}
// [/listing]

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

 private:
  Canvas& canvas_;
  Color color_;
  int row_end_;
};

// [listing pixel_writer]
/// What every traversal needs from a writer: whole spans of a row, single pixels, and the end of
/// the pixels of a row it may touch (the canvas width, or a tile's right end). RowWriter and
/// CountingWriter are the two; each traversal is one template over them.
template <class Writer>
concept PixelWriter = requires(Writer writer, int x, int y) {
  writer.span(y, x, x + 1);  // pixels x_begin <= x < x_end of row y
  writer.pixel(x, y);
  { writer.width() } -> std::convertible_to<int>;
};
// [/listing]

static_assert(PixelWriter<RowWriter> && PixelWriter<CountingWriter>);

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

/// The single-triangle entry of a traversal: the setup, then fill(setup, writer) with the writer
/// that suits the canvas. Nothing is drawn when the setup is empty.
template <class Fill>
void set_up_and_fill(Canvas& canvas, const Triangle& triangle, Color color, Fill&& fill) {
  const auto setup = setup_triangle(triangle, canvas.width(), canvas.height());
  if (!setup) return;
  with_writer(canvas, color, [&](auto& writer) { fill(*setup, writer); });
}

}  // namespace tri::ch08
