#include "common/canvas.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace tri {

Canvas::Canvas(int width, int height, Color background) : width_(width), height_(height) {
  if (width < 1 || height < 1 || width > max_canvas_side || height > max_canvas_side) {
    throw std::invalid_argument("canvas size " + std::to_string(width) + "x" +
                                std::to_string(height) + " is outside 1.." +
                                std::to_string(max_canvas_side) + " on a side");
  }
  pixels_.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), background);
}

void Canvas::fill_span(int y, int x_begin, int x_end, Color color) noexcept {
  if (x_end <= x_begin) return;
  if (y < 0 || y >= height_) {
    outside_writes_ += static_cast<std::uint64_t>(static_cast<std::int64_t>(x_end) - x_begin);
    return;
  }
  const int first = std::max(x_begin, 0);
  const int last = std::min(x_end, width_);
  const auto clipped = static_cast<std::int64_t>(x_end) - x_begin - std::max(last - first, 0);
  // Written only when nonzero: threads filling disjoint rows of one canvas then share no data.
  if (clipped != 0) outside_writes_ += static_cast<std::uint64_t>(clipped);
  if (first >= last) return;
  const auto begin = pixels_.begin() + static_cast<std::ptrdiff_t>(index(first, y));
  std::fill(begin, begin + (last - first), color);
  if (!counts_.empty()) {
    const auto counts = counts_.begin() + static_cast<std::ptrdiff_t>(index(first, y));
    std::for_each(counts, counts + (last - first), [](std::uint32_t& c) { ++c; });
  }
}

void Canvas::clear(Color color) noexcept {
  std::fill(pixels_.begin(), pixels_.end(), color);
  std::fill(counts_.begin(), counts_.end(), 0u);
  outside_writes_ = 0;
}

void Canvas::enable_write_counts() {
  counts_.assign(pixels_.size(), 0u);
}

}  // namespace tri
