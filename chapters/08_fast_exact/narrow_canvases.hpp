/// @file
/// Step 8 · only the bytes the picture needs: canvases of one byte per pixel (a palette index,
/// for a scene of at most 255 colours) and of one bit per pixel (covered or not, for a one-colour
/// scene or when only coverage is wanted), with the writers that let step 3's span traversal fill
/// them (each writer's row-store hook). The traversal decides which pixels to write exactly as for
/// the RGBA8 canvas; only the store differs.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <vector>

#include "chapters/08_fast_exact/instruction_sets.hpp"
#include "chapters/08_fast_exact/pixel_writers.hpp"
#include "chapters/08_fast_exact/simd.hpp"
#include "chapters/08_fast_exact/triangle_setup.hpp"
#include "common/triangle_algorithm.hpp"

namespace tri::ch08 {

/// W×H pixels of one byte each, y up like Canvas: 0 is the background, 1 to 255 palette entries.
class IndexCanvas {
 public:
  IndexCanvas(int width, int height);
  int width() const noexcept { return width_; }
  int height() const noexcept { return height_; }
  std::uint8_t index(int x, int y) const noexcept { return bytes_[offset(x, y)]; }
  /// Row y's bytes (precondition: 0 <= y < height).
  std::uint8_t* row(int y) noexcept { return bytes_.data() + offset(0, y); }

 private:
  std::size_t offset(int x, int y) const noexcept {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
           static_cast<std::size_t>(x);
  }
  int width_, height_;
  std::vector<std::uint8_t> bytes_;
};

/// W×H pixels of one bit each, y up: 1 where a triangle covers the pixel. Each row is whole
/// 64-bit words; pixel x of a row is bit x % 64 of word x / 64.
class MaskCanvas {
 public:
  MaskCanvas(int width, int height);
  int width() const noexcept { return width_; }
  int height() const noexcept { return height_; }
  int words_per_row() const noexcept { return words_per_row_; }
  bool covered(int x, int y) const noexcept { return (words_[word(x, y)] >> (x % 64)) & 1u; }
  /// Row y's words (precondition: 0 <= y < height).
  std::uint64_t* row(int y) noexcept { return words_.data() + word(0, y); }

 private:
  std::size_t word(int x, int y) const noexcept {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(words_per_row_) +
           static_cast<std::size_t>(x / 64);
  }
  int width_, height_, words_per_row_;
  std::vector<std::uint64_t> words_;
};

/// Writes one palette index into an IndexCanvas: a span is one memset.
class IndexWriter {
 public:
  IndexWriter(IndexCanvas& canvas, std::uint8_t index) noexcept : canvas_(canvas), index_(index) {}
  void span(int y, int x_begin, int x_end) noexcept {
    std::memset(canvas_.row(y) + x_begin, index_, static_cast<std::size_t>(x_end - x_begin));
  }
  void pixel(int x, int y) noexcept { canvas_.row(y)[x] = index_; }
  int width() const noexcept { return canvas_.width(); }
  template <InstructionSet>
  SpanRows<IndexWriter> rows_from(int) noexcept {
    return {*this};
  }

 private:
  IndexCanvas& canvas_;
  std::uint8_t index_;
};

// [listing mask_writer]
/// Sets bits of a MaskCanvas: a span is a partial first word, whole words, a partial last word.
class MaskWriter {
 public:
  explicit MaskWriter(MaskCanvas& canvas) noexcept : canvas_(canvas) {}
  void span(int y, int x_begin, int x_end) noexcept { set_bits(canvas_.row(y), x_begin, x_end); }
  void pixel(int x, int y) noexcept { canvas_.row(y)[x / 64] |= std::uint64_t{1} << (x % 64); }
  int width() const noexcept { return canvas_.width(); }

  /// The span fill's rows from y up: the row's words move up by the stride instead of being asked
  /// for by y. One bit per pixel needs no vector stores: every copy sets the same words.
  struct Rows {
    std::uint64_t* row;
    std::ptrdiff_t stride;
    void fill(int, int x_begin, int x_end) noexcept { set_bits(row, x_begin, x_end); }
    void next_row() noexcept { row += stride; }
  };
  template <InstructionSet>
  Rows rows_from(int y) noexcept {
    return {canvas_.row(y), canvas_.words_per_row()};
  }

  /// Sets bits x_begin <= x < x_end (0 <= x_begin < x_end) of one row's words.
  static void set_bits(std::uint64_t* words, int x_begin, int x_end) noexcept {
    // Pixel offsets are never negative: unsigned shifts and masks instead of signed / and %.
    const auto begin = static_cast<unsigned>(x_begin), last_x = static_cast<unsigned>(x_end - 1);
    const unsigned first = begin / 64, last = last_x / 64;
    const std::uint64_t from_begin = ~std::uint64_t{0} << (begin % 64);
    const std::uint64_t to_end = ~std::uint64_t{0} >> (63 - last_x % 64);
    if (first == last) {
      words[first] |= from_begin & to_end;
      return;
    }
    words[first] |= from_begin;
    for (unsigned w = first + 1; w < last; ++w) words[w] = ~std::uint64_t{0};
    words[last] |= to_end;
  }

 private:
  MaskCanvas& canvas_;
};
// [/listing]

/// On a little-endian processor a row of the mask is one string of bits in byte order, so up to
/// 57 neighbouring pixels lie within the 8 bytes from the first one's byte (or the row's last 8).
inline constexpr bool mask_window_stores = std::endian::native == std::endian::little;

static_assert(PixelWriter<IndexWriter> && PixelWriter<MaskWriter>);

}  // namespace tri::ch08

namespace tri {

/// A narrow canvas and what to write into it: the registry's narrow draws take one.
struct NarrowTarget {
  ch08::IndexCanvas* indices = nullptr;  ///< index8's canvas, or
  ch08::MaskCanvas* mask = nullptr;      ///< mask1's
  /// index8: each triangle's palette index, in the order of the triangles drawn.
  std::span<const std::uint8_t> index_of = {};

  int width() const noexcept { return mask != nullptr ? mask->width() : indices->width(); }
  int height() const noexcept { return mask != nullptr ? mask->height() : indices->height(); }
  /// Calls fill(writer) with the writer of the batch's triangle i.
  template <class Fill>
  void with_writer(std::size_t i, Fill&& fill) {
    if (mask != nullptr) {
      ch08::MaskWriter writer(*mask);
      fill(writer);
    } else {
      ch08::IndexWriter writer(*indices, index_of[i]);
      fill(writer);
    }
  }
};

}  // namespace tri

namespace tri::ch08 {

/// Step 8 · step 3's spans into a narrow target, one triangle after the other (the registry's
/// draw_narrow entry of fast_spans).
void draw_narrow_spans(NarrowTarget& target, std::span<const SceneTriangle> triangles);

/// Step 8 · step 3's spans into one byte per pixel: the triangle's pixels set to `index`.
void draw_triangle_spans_index8(IndexCanvas& canvas, const Triangle& triangle, std::uint8_t index);

/// Step 8 · step 3's spans into one bit per pixel: the triangle's pixels set to 1.
void draw_triangle_spans_mask1(MaskCanvas& canvas, const Triangle& triangle);

/// The widest candidate pixels fill_mask_lanes draws: 32 columns, four vectors of eight lanes
/// (48 columns in six were slower on the machine of the performance notes).
inline constexpr int max_mask_lanes = 32;

/// True when fill_mask_lanes can draw the setup: its candidate pixels are at most max_mask_lanes
/// columns wide, its edge values fit in 32-bit lanes (step 5's fits_32_bit_lanes: its argument
/// holds for lanes up to 31 pixels right of the candidate pixels' first column and 4 rows above
/// their last row, with every |value| below 2^30), and the mask's rows are little-endian bit
/// strings (mask_window_stores).
constexpr bool fits_mask_lanes(const TriangleSetup& setup) noexcept {
  return mask_window_stores && setup.range.max.x - setup.range.min.x < max_mask_lanes &&
         fits_32_bit_lanes(setup);
}

/// Step 8 · a triangle at most 32 pixels wide into one bit per pixel, without walking its spans
/// (no divisions to set up, no bounds to carry per row): per row, 8 to 32 lanes test the three
/// edge functions (step 5's lane test), their signs gather into the row's bits, and one 8-byte OR
/// sets them at once. The pixels of draw_triangle_spans_mask1. Precondition:
/// fits_mask_lanes(setup). In the copy for `set` (by default the widest the host runs).
void fill_mask_lanes(MaskCanvas& canvas, const TriangleSetup& setup,
                     InstructionSet set = widest_instruction_set()) noexcept;

/// The two restricted to rows first_row..last_row, so a huge triangle can be drawn in bands.
void draw_triangle_spans_index8_rows(IndexCanvas& canvas, const Triangle& triangle,
                                     std::uint8_t index, int first_row, int last_row);
void draw_triangle_spans_mask1_rows(MaskCanvas& canvas, const Triangle& triangle, int first_row,
                                    int last_row);

}  // namespace tri::ch08
