#include "clip_segment.hpp"

#include <algorithm>

namespace tri::ch05 {

std::optional<std::array<glm::dvec2, 2>> clip_segment_to_pixels(glm::dvec2 a, glm::dvec2 b,
                                                                glm::ivec2 first,
                                                                glm::ivec2 last) noexcept {
  const glm::dvec2 low = glm::dvec2(first) - 0.5, high = glm::dvec2(last) + 0.5, d = b - a;
  double t0 = 0, t1 = 1;
  for (int axis = 0; axis < 2; ++axis) {
    // Inside means a + t d >= low and a + t d <= high: each side cuts the range of t.
    const std::array<std::array<double, 2>, 2> sides{
        {{-d[axis], a[axis] - low[axis]}, {d[axis], high[axis] - a[axis]}}};
    for (const auto& [p, q] : sides) {
      if (p == 0) {
        if (q < 0) return std::nullopt;  // parallel to this side and outside it
        continue;
      }
      const double t = q / p;
      if (p < 0) t0 = std::max(t0, t);
      if (p > 0) t1 = std::min(t1, t);
    }
  }
  if (t0 > t1) return std::nullopt;
  return std::array<glm::dvec2, 2>{a + t0 * d, a + t1 * d};
}

}  // namespace tri::ch05
