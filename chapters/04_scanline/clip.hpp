/// @file
/// Clipping for the scanline steps: the rows of a y range that lie on the canvas, and a span
/// between two boundary ends cut to the canvas before a single pixel is written.
#pragma once

#include <cstdint>

#include "common/canvas.hpp"
#include "common/color.hpp"

namespace tri::ch04 {

/// The rows first <= y <= last of a range that lie on the canvas; empty when first > last.
struct RowsOnCanvas {
  std::int64_t first;
  std::int64_t last;
};

/// The rows of [low, high] that lie on the canvas, so a loop over a triangle with vertices at
/// ±2^30 visits at most canvas.height() rows instead of two billion.
RowsOnCanvas rows_on_canvas(const Canvas& canvas, std::int64_t low, std::int64_t high) noexcept;

/// Sets the pixels of row y from x = a to x = b, both ends included, in whichever order a and b
/// come (the article's `if (A.x > B.x) swap`). The span is clipped to the canvas first, so
/// nothing is ever written outside it.
void fill_span_between(Canvas& canvas, std::int64_t y, std::int64_t a, std::int64_t b,
                       Color color) noexcept;

/// Sets pixel (x, y) only if it is on the canvas (the article's image.set ignores the rest).
void put_pixel_if_on_canvas(Canvas& canvas, std::int64_t x, std::int64_t y, Color color) noexcept;

}  // namespace tri::ch04
