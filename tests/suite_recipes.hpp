// What the 10,000-triangle suites share: one recipe per scene family on a 256x256 canvas.
#pragma once

#include <cstdint>

#include "measure/scene_generators.hpp"

namespace tri::test {

/// 10,000 triangles of one kind on a 256x256 canvas, vertices on the 1/256 grid.
inline SceneRecipe ten_thousand(SceneRecipe::Kind kind, double min_extent, double max_extent,
                                std::uint64_t seed) {
  SceneRecipe r;
  r.kind = kind;
  r.width = 256;
  r.height = 256;
  r.triangles = 10000;
  r.min_extent = min_extent;
  r.max_extent = max_extent;
  r.grid_bits = 8;
  r.seed = seed;
  return r;
}

}  // namespace tri::test
