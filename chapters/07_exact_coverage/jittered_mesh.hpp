/// @file
/// The book's test mesh: a grid of cells, each cut into two triangles, its inner vertices moved
/// by a seeded jitter and snapped to the 1/256 grid, so the triangles tile a rectangle exactly and
/// many of their shared edges cross pixel centres at awkward angles.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

#include "common/triangle_algorithm.hpp"

namespace tri::ch07 {

/// columns x rows square cells of `cell` pixels from `origin`, each cut along its rising
/// diagonal; every vertex off the border moved by up to ±jitter x cell in x and in y (seeded),
/// then every vertex snapped to the nearest 1/256 of a pixel. A jitter below 1/6 keeps every
/// cell convex, so no triangle folds over its neighbour.
std::vector<Triangle> jittered_mesh(int columns, int rows, glm::dvec2 origin, double cell,
                                    double jitter, std::uint64_t seed);

}  // namespace tri::ch07
