#include "chapters/04_scanline/clip.hpp"

#include <algorithm>
#include <utility>

namespace tri::ch04 {

RowsOnCanvas rows_on_canvas(const Canvas& canvas, std::int64_t low, std::int64_t high) noexcept {
  return {std::max<std::int64_t>(low, 0), std::min<std::int64_t>(high, canvas.height() - 1)};
}

void fill_span_between(Canvas& canvas, std::int64_t y, std::int64_t a, std::int64_t b,
                       Color color) noexcept {
  if (a > b) std::swap(a, b);
  if (y < 0 || y >= canvas.height()) return;
  const std::int64_t first = std::max<std::int64_t>(a, 0);
  const std::int64_t last = std::min<std::int64_t>(b, canvas.width() - 1);
  // Both ends now fit in int: they lie on the canvas.
  if (first <= last) {
    canvas.fill_span(static_cast<int>(y), static_cast<int>(first), static_cast<int>(last + 1),
                     color);
  }
}

void put_pixel_if_on_canvas(Canvas& canvas, std::int64_t x, std::int64_t y, Color color) noexcept {
  if (x < 0 || y < 0 || x >= canvas.width() || y >= canvas.height()) return;
  canvas.put_pixel(static_cast<int>(x), static_cast<int>(y), color);
}

}  // namespace tri::ch04
