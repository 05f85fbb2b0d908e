/// @file
/// A mesh for the chapter's tests and figures: a grid of cells, each cut into two triangles, the
/// inner vertices moved by a seeded jitter on the 1/256 grid, so the triangles tile a rectangle.
#pragma once

#include <cstdint>
#include <vector>

#include "common/triangle_algorithm.hpp"

namespace tri::ch10 {

/// columns x rows cells of `cell` pixels each, from (origin, origin), every cell cut along a
/// diagonal; inner vertices moved by up to `jitter_256ths` / 256 of a pixel in x and y.
std::vector<Triangle> jittered_mesh(int columns, int rows, int cell, double origin,
                                    int jitter_256ths, std::uint64_t seed);

}  // namespace tri::ch10
