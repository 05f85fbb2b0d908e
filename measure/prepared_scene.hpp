/// @file
/// One scene of a measuring suite, and that scene made ready once so no timed run allocates or
/// copies it: what the report and the external peers' adapters draw.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "common/scene.hpp"
#include "common/triangle_algorithm.hpp"
#include "measure/scene_generators.hpp"

namespace tri {

/// One scene of a suite.
struct SuiteScene {
  std::string name;  ///< the scene kind: tiny, medium, large, slivers, mesh, fan, mixed
  std::string grid;  ///< "integer" (vertices on pixel centres) or "1/256"
  SceneRecipe recipe;
  bool mesh = false;  ///< shared edges, so gaps and overdraw mean something
};

/// A suite scene made ready once, so no timed run allocates or copies it.
struct PreparedScene {
  SuiteScene suite;
  Scene scene;
  std::vector<SceneTriangle> triangles;  ///< the scene's triangles, as draw_triangles takes them
  Scene error_scene;    ///< what the error is measured on: the scene, or its first triangles
  PreparedBatch batch;  ///< the triangles checked once: what the algorithms' timed draws take
};

/// Generates the scene, its triangle list and its prepared batch; the error scene keeps the first
/// error_triangle_limit triangles (all of them for 0).
PreparedScene prepare_scene(const SuiteScene& suite, std::size_t error_triangle_limit);

}  // namespace tri
