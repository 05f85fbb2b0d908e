#include "chapters/09_anti_aliasing/coverage_canvas.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tri::ch09 {

CoverageCanvas::CoverageCanvas(int width, int height) : width_(width), height_(height) {
  if (width <= 0 || height <= 0) {
    throw std::invalid_argument("a coverage canvas needs a positive width and height");
  }
  values_.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0.0f);
}

std::uint16_t coverage_16(double coverage) noexcept {
  const double c = std::clamp(coverage, 0.0, 1.0);
  return static_cast<std::uint16_t>(std::floor(c * 65535.0 + 0.5));
}

std::vector<std::uint8_t> CoverageCanvas::pgm_16() const {
  const std::string header =
      "P5\n" + std::to_string(width_) + " " + std::to_string(height_) + "\n65535\n";
  std::vector<std::uint8_t> pgm(header.begin(), header.end());
  pgm.reserve(pgm.size() + values_.size() * 2);
  for (int y = height_ - 1; y >= 0; --y) {  // the file's first row is the top
    for (int x = 0; x < width_; ++x) {
      const std::uint16_t v = coverage_16(at(x, y));
      pgm.push_back(static_cast<std::uint8_t>(v >> 8));
      pgm.push_back(static_cast<std::uint8_t>(v & 0xff));
    }
  }
  return pgm;
}

}  // namespace tri::ch09
