#include "chapters/07_exact_coverage/jittered_mesh.hpp"

#include <cmath>

#include "common/random.hpp"

namespace tri::ch07 {

std::vector<Triangle> jittered_mesh(int columns, int rows, glm::dvec2 origin, double cell,
                                    double jitter, std::uint64_t seed) {
  Random random(seed);
  std::vector<glm::dvec2> points;
  for (int j = 0; j <= rows; ++j) {
    for (int i = 0; i <= columns; ++i) {
      const bool border = i == 0 || j == 0 || i == columns || j == rows;
      const double jx = border ? 0 : random.real(-jitter, jitter) * cell;
      const double jy = border ? 0 : random.real(-jitter, jitter) * cell;
      points.emplace_back(std::round((origin.x + i * cell + jx) * 256) / 256,
                          std::round((origin.y + j * cell + jy) * 256) / 256);
    }
  }
  const auto at = [&](int i, int j) {
    return points[static_cast<std::size_t>(j * (columns + 1) + i)];
  };
  std::vector<Triangle> mesh;
  for (int j = 0; j < rows; ++j) {
    for (int i = 0; i < columns; ++i) {
      mesh.push_back({{at(i, j), at(i + 1, j), at(i + 1, j + 1)}});
      mesh.push_back({{at(i, j), at(i + 1, j + 1), at(i, j + 1)}});
    }
  }
  return mesh;
}

}  // namespace tri::ch07
