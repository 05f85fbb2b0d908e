/// @file
/// The canvas every chapter draws on: W×H RGBA8 pixels, y up, origin at the bottom-left.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec2.hpp>

#include "common/color.hpp"

namespace tri {

/// Largest canvas side the tutorial accepts (@ref design_canvas "docs/DESIGN.md section 3").
inline constexpr int max_canvas_side = 16384;

/// Where pixel (x, y) of a grid `width` pixels wide sits in its array, rows stored one after the
/// other from row 0 (precondition: 0 <= x < width, 0 <= y).
inline std::size_t pixel_index(int x, int y, int width) noexcept {
  return static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
         static_cast<std::size_t>(x);
}

/// A grid of RGBA8 pixels. Pixel (x, y) is the sample at the point (x, y): integer coordinates are
/// pixel centres, x grows to the right and y grows **up**. Rows are stored bottom row first.
///
/// Writes outside the canvas are ignored (and counted), never undefined behaviour. When write
/// counting is on, every accepted write also increments that pixel's counter, which is how the
/// tutorial shows overdraw (count > 1) and gaps (count 0).
class Canvas {
 public:
  /// Throws std::invalid_argument unless 1 <= width, height <= max_canvas_side.
  Canvas(int width, int height, Color background = colors::black);

  int width() const noexcept { return width_; }
  int height() const noexcept { return height_; }

  /// True when (x, y) is a pixel of this canvas.
  bool contains(int x, int y) const noexcept {
    // One unsigned comparison per axis also rejects negative values.
    return static_cast<unsigned>(x) < static_cast<unsigned>(width_) &&
           static_cast<unsigned>(y) < static_cast<unsigned>(height_);
  }
  bool contains(glm::ivec2 p) const noexcept { return contains(p.x, p.y); }

  /// Sets one pixel; a pixel outside the canvas is ignored and counted in outside_writes().
  void put_pixel(int x, int y, Color color) noexcept {
    if (!contains(x, y)) {
      ++outside_writes_;
      return;
    }
    const auto i = index(x, y);
    pixels_[i] = color;
    if (!counts_.empty()) ++counts_[i];
  }
  void put_pixel(glm::ivec2 p, Color color) noexcept { put_pixel(p.x, p.y, color); }

  /// Sets the pixels x_begin <= x < x_end of row y, clipped to the canvas (the fast path for
  /// span-based rasterizers). Pixels cut off by the clip are counted in outside_writes(). Threads
  /// may fill disjoint rows of one canvas at once, as long as their spans lie inside it.
  void fill_span(int y, int x_begin, int x_end, Color color) noexcept;

  /// The colour of a pixel of the canvas (precondition: contains(x, y)).
  Color pixel(int x, int y) const noexcept { return pixels_[index(x, y)]; }

  /// Paints every pixel and resets the counters.
  void clear(Color color) noexcept;

  /// Starts counting writes per pixel (all counts start at zero).
  void enable_write_counts();
  bool write_counts_enabled() const noexcept { return !counts_.empty(); }
  /// How many times pixel (x, y) was written since counting started (0 when counting is off).
  std::uint32_t write_count(int x, int y) const noexcept {
    return counts_.empty() ? 0 : counts_[index(x, y)];
  }

  /// Writes that fell outside the canvas and were ignored.
  std::uint64_t outside_writes() const noexcept { return outside_writes_; }

  /// All pixels, bottom row first.
  std::span<const Color> pixels() const noexcept { return pixels_; }
  /// One row of pixels, for code that writes spans itself (precondition: 0 <= y < height).
  std::span<Color> row(int y) noexcept {
    return std::span<Color>(pixels_).subspan(index(0, y), width_);
  }
  /// All write counters, bottom row first (empty when counting is off).
  std::span<const std::uint32_t> write_counts() const noexcept { return counts_; }

 private:
  std::size_t index(int x, int y) const noexcept { return pixel_index(x, y, width_); }

  int width_;
  int height_;
  std::vector<Color> pixels_;
  std::vector<std::uint32_t> counts_;
  std::uint64_t outside_writes_ = 0;
};

}  // namespace tri
