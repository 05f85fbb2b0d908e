#include "chapters/07_exact_coverage/jittered_mesh.hpp"

#include <cmath>

namespace tri::ch07 {
namespace {

double snapped(double value, int bits) {
  const double scale = std::ldexp(1.0, bits);
  return std::floor(value * scale + 0.5) / scale;
}

}  // namespace

std::vector<Triangle> jittered_grid_triangles(const JitteredGrid& grid, Random& random) {
  const auto move = [&](bool pinned, double size) {
    return pinned ? 0.0 : random.real(-grid.jitter, grid.jitter) * size;
  };
  std::vector<glm::dvec2> points;
  for (int j = 0; j <= grid.rows; ++j) {
    for (int i = 0; i <= grid.columns; ++i) {
      const bool left_or_right = i == 0 || i == grid.columns;
      const bool bottom_or_top = j == 0 || j == grid.rows;
      const bool pinned = grid.pin_border_vertices && (left_or_right || bottom_or_top);
      const double dx = move(pinned || left_or_right, grid.cell.x);
      const double dy = move(pinned || bottom_or_top, grid.cell.y);
      points.emplace_back(snapped(grid.origin.x + i * grid.cell.x + dx, grid.grid_bits),
                          snapped(grid.origin.y + j * grid.cell.y + dy, grid.grid_bits));
    }
  }
  const auto at = [&](int i, int j) {
    return points[static_cast<std::size_t>(j * (grid.columns + 1) + i)];
  };
  std::vector<Triangle> mesh;
  for (int j = 0; j < grid.rows; ++j) {
    for (int i = 0; i < grid.columns; ++i) {
      if (grid.alternate_diagonals && (i + j) % 2 != 0) {  // the falling diagonal
        mesh.push_back({{at(i, j), at(i + 1, j), at(i, j + 1)}});
        mesh.push_back({{at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)}});
      } else {  // the rising diagonal
        mesh.push_back({{at(i, j), at(i + 1, j), at(i + 1, j + 1)}});
        mesh.push_back({{at(i, j), at(i + 1, j + 1), at(i, j + 1)}});
      }
    }
  }
  return mesh;
}

std::vector<Triangle> jittered_mesh(int columns, int rows, glm::dvec2 origin, double cell,
                                    double jitter, std::uint64_t seed) {
  Random random(seed);
  return jittered_grid_triangles(
      {.columns = columns, .rows = rows, .origin = origin, .cell = {cell, cell}, .jitter = jitter},
      random);
}

}  // namespace tri::ch07
