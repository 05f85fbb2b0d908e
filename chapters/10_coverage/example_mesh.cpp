#include "chapters/10_coverage/example_mesh.hpp"

#include "common/random.hpp"

namespace tri::ch10 {

std::vector<Triangle> jittered_mesh(int columns, int rows, int cell, double origin,
                                    int jitter_256ths, std::uint64_t seed) {
  Random random(seed);
  std::vector<glm::dvec2> vertex;
  for (int j = 0; j <= rows; ++j) {
    for (int i = 0; i <= columns; ++i) {
      const bool border = i == 0 || j == 0 || i == columns || j == rows;
      const int jx = border ? 0 : random.integer(-jitter_256ths, jitter_256ths);
      const int jy = border ? 0 : random.integer(-jitter_256ths, jitter_256ths);
      vertex.push_back({origin + i * cell + jx / 256.0, origin + j * cell + jy / 256.0});
    }
  }
  const auto at = [&](int i, int j) { return vertex[j * (columns + 1) + i]; };
  std::vector<Triangle> triangles;
  for (int j = 0; j < rows; ++j) {
    for (int i = 0; i < columns; ++i) {
      triangles.push_back({{at(i, j), at(i + 1, j), at(i + 1, j + 1)}});
      triangles.push_back({{at(i, j), at(i + 1, j + 1), at(i, j + 1)}});
    }
  }
  return triangles;
}

}  // namespace tri::ch10
