#include "chapters/04_scanline/boundaries.hpp"

#include <utility>

namespace tri::ch04 {

// [listing sort_by_y]
SortedTriangle sort_by_y(glm::ivec2 a, glm::ivec2 b, glm::ivec2 c) noexcept {
  if (a.y > b.y) std::swap(a, b);
  if (a.y > c.y) std::swap(a, c);
  if (b.y > c.y) std::swap(b, c);
  return {a, b, c};
}
// [/listing]

// [listing truncated_boundary_x]
std::int64_t truncated_boundary_x(glm::ivec2 start, glm::ivec2 end, std::int64_t step,
                                  std::int64_t steps) noexcept {
  // |dx * step| < 2^31 * 2^31 = 2^62: fits in 64 bits. C++ division truncates toward zero.
  const std::int64_t dx = static_cast<std::int64_t>(end.x) - start.x;
  return start.x + dx * step / steps;
}
// [/listing]

}  // namespace tri::ch04
