#include "chapters/01_lines/line_reference.hpp"

#include <cstdlib>
#include <utility>

namespace tri::ch01 {
namespace {

__extension__ using Wide = __int128;  // 2 dm k reaches 2^63 for endpoints at ±2^30

// floor(a / b) for b > 0, which C++'s truncating division is not for negative a.
Wide floor_div(Wide a, Wide b) {
  const Wide q = a / b;
  return (a % b != 0 && a < 0) ? q - 1 : q;
}

struct MajorMinor {
  bool x_major;
  std::int64_t a0, b0, a1, b1;  // (major, minor) of both ends, a0 <= a1
};

MajorMinor orient(glm::ivec2 p0, glm::ivec2 p1) {
  const bool x_major = std::abs(static_cast<std::int64_t>(p1.x) - p0.x) >=
                       std::abs(static_cast<std::int64_t>(p1.y) - p0.y);
  MajorMinor m{x_major, x_major ? p0.x : p0.y, x_major ? p0.y : p0.x, x_major ? p1.x : p1.y,
               x_major ? p1.y : p1.x};
  if (m.a0 > m.a1) {
    std::swap(m.a0, m.a1);
    std::swap(m.b0, m.b1);
  }
  return m;
}

// [listing exact_pixel_at]
ExactLinePixel pixel_at(const MajorMinor& m, std::int64_t major) {
  const std::int64_t n = m.a1 - m.a0;
  const std::int64_t k = major - m.a0;
  std::int64_t minor = m.b0;
  bool tie = false;
  if (n > 0) {
    // minor = b0 + db k / n; the nearest integer is floor((2 db k + n) / 2n), a tie when exact.
    const Wide numerator = Wide{2} * (m.b1 - m.b0) * k + n;
    minor = m.b0 + static_cast<std::int64_t>(floor_div(numerator, Wide{2} * n));
    tie = numerator % (Wide{2} * n) == 0;
  }
  const auto a = static_cast<int>(major);
  const auto b = static_cast<int>(minor);
  return {m.x_major ? glm::ivec2(a, b) : glm::ivec2(b, a), tie};
}
// [/listing]

}  // namespace

ExactLinePixel exact_line_pixel_at(glm::ivec2 p0, glm::ivec2 p1, std::int64_t major) {
  return pixel_at(orient(p0, p1), major);
}

std::vector<ExactLinePixel> exact_line_pixels(glm::ivec2 p0, glm::ivec2 p1) {
  const MajorMinor m = orient(p0, p1);
  std::vector<ExactLinePixel> pixels;
  pixels.reserve(static_cast<std::size_t>(m.a1 - m.a0) + 1);
  for (std::int64_t a = m.a0; a <= m.a1; ++a) pixels.push_back(pixel_at(m, a));
  return pixels;
}

}  // namespace tri::ch01
