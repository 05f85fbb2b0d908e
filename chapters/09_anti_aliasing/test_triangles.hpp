// What chapter 09's tests share: seeded random triangles on the oracle's 1/256 grid.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

#include "common/random.hpp"
#include "common/triangle_algorithm.hpp"

namespace tri::ch09::test {

/// `count` triangles whose vertices lie on the 1/256 grid within [low, high] (pixels).
inline std::vector<Triangle> random_triangles(int count, std::uint64_t seed, glm::ivec2 low,
                                              glm::ivec2 high) {
  Random random(seed);
  std::vector<Triangle> triangles(static_cast<std::size_t>(count));
  for (auto& t : triangles) {
    for (auto& v : t) {
      v = {random.integer(low.x * 256, high.x * 256) / 256.0,
           random.integer(low.y * 256, high.y * 256) / 256.0};
    }
  }
  return triangles;
}

}  // namespace tri::ch09::test
