/// @file
/// A canvas of coverage: for every pixel, how much of it the triangles drawn so far cover, summed.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "common/canvas.hpp"

namespace tri::ch09 {

/// A coverage as the 16-bit value the PGM output stores: c clamped to [0, 1], then
/// round(65535 x c), halves up.
std::uint16_t coverage_16(double coverage) noexcept;

/// Coverage values per pixel, row-major with row 0 at the bottom (y up, as the canvas). Each
/// value is the sum of the coverages added to it (1 is a full pixel). A float holds every
/// sampled coverage (k / n^2, n <= 16) exactly and an area to better than 1/65535.
class CoverageCanvas {
 public:
  /// A canvas of width x height pixels, all 0 (throws std::invalid_argument unless both > 0).
  CoverageCanvas(int width, int height);

  int width() const noexcept { return width_; }
  int height() const noexcept { return height_; }
  float at(int x, int y) const { return values_[index(x, y)]; }
  /// Row y's first value (row 0 at the bottom), for code that walks a row itself.
  float* row(int y) noexcept { return values_.data() + index(0, y); }
  /// Sets every pixel to 0.
  void clear() noexcept { std::fill(values_.begin(), values_.end(), 0.0f); }
  /// Sets pixel (x, y), which must lie on the canvas, to c.
  void set(int x, int y, float c) { values_[index(x, y)] = c; }
  /// Adds c to pixel (x, y), which must lie on the canvas.
  void add(int x, int y, float c) { values_[index(x, y)] += c; }
  /// Composites coverage c over pixel (x, y) as alpha: v + c (1 - v), the "over" of Porter and
  /// Duff with the coverage as the new layer's alpha.
  void over(int x, int y, float c) {
    float& v = values_[index(x, y)];
    v += c * (1.0f - v);
  }

  /// The canvas as a 16-bit binary PGM (P5, maxval 65535, big-endian, top row first): each
  /// value clamped to [0, 1] and stored as round(65535 x value).
  std::vector<std::uint8_t> pgm_16() const;

 private:
  std::size_t index(int x, int y) const noexcept { return pixel_index(x, y, width_); }

  int width_;
  int height_;
  std::vector<float> values_;
};

}  // namespace tri::ch09
