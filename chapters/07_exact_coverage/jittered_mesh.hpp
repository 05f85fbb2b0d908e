/// @file
/// The book's test mesh: a grid of cells, each cut into two triangles, its inner vertices moved
/// by a seeded jitter and snapped to a fine grid, so the triangles tile a rectangle exactly and
/// many of their shared edges cross pixel centres at awkward angles. Chapter 07's figures use it,
/// and so do the seeded mesh scenes every measurement draws (measure/scene_generators).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

#include "common/random.hpp"
#include "common/triangle_algorithm.hpp"

namespace tri::ch07 {

/// How a jittered grid is laid out.
struct JitteredGrid {
  int columns = 1;
  int rows = 1;
  glm::dvec2 origin{0, 0};  ///< the grid's bottom-left corner
  glm::dvec2 cell{1, 1};    ///< a cell's width and height in pixels
  /// The largest move of a vertex, as a fraction of the cell, in x and in y. Below 1/6 every
  /// cell stays convex, so no triangle folds over its neighbour.
  double jitter = 0.15;
  int grid_bits = 8;  ///< every vertex snapped to the nearest 1/2^grid_bits of a pixel
  /// true: a vertex on the border does not move at all; false: one on the bottom or top border
  /// still moves in x, one on the left or right border in y (the rectangle stays the same).
  bool pin_border_vertices = true;
  bool alternate_diagonals = false;  ///< cut cells along alternating diagonals, not all rising
};

/// The grid's triangles, two per cell, cells row by row from the bottom, every jitter drawn from
/// `random` (x then y, vertex by vertex, row by row; nothing for a coordinate that does not move).
std::vector<Triangle> jittered_grid_triangles(const JitteredGrid& grid, Random& random);

/// columns x rows square cells of `cell` pixels from `origin`, each cut along its rising
/// diagonal; every vertex off the border moved by up to ±jitter x cell in x and in y (seeded),
/// then every vertex snapped to the nearest 1/256 of a pixel.
std::vector<Triangle> jittered_mesh(int columns, int rows, glm::dvec2 origin, double cell,
                                    double jitter, std::uint64_t seed);

}  // namespace tri::ch07
