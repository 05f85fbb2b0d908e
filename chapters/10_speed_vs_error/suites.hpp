/// @file
/// The scene suites the report draws with every algorithm: seven scene kinds, each on the integer
/// grid and on the 1/256 grid, in three sizes (a tiny one for the tests, quick, full).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "measure/prepared_scene.hpp"
#include "measure/scene_generators.hpp"
#include "measure/timing.hpp"

namespace tri::ch10 {

/// How big a run is.
enum class SuiteSize {
  tiny,   ///< a few triangles on a small canvas: for the tests, seconds of nothing
  quick,  ///< the default: every algorithm in about a minute on two cores
  full,   ///< --full: a 512x512 canvas, the 100,000-triangle mesh, more and longer samples
};

/// "tiny", "quick" or "full".
std::string_view size_name(SuiteSize size) noexcept;

/// The label of a vertex grid: "integer" for 0 bits, "1/256" for 8, "1/2^n" otherwise.
std::string grid_label(int grid_bits);

/// Every scene of a suite: each kind on the integer grid, then each kind on the 1/256 grid.
std::vector<SuiteScene> scene_suite(SuiteSize size);

/// Everything a run needs: the scenes, the timing and how much of each scene the error uses.
struct BenchSettings {
  SuiteSize size = SuiteSize::quick;
  std::vector<SuiteScene> scenes;
  TimingPlan timing;
  /// The error is measured on the first this many triangles of each scene (0: all of them).
  std::size_t error_triangle_limit = 0;
  /// Square canvases whose one-thread write ceiling the report quotes beside the suite's.
  std::vector<int> reference_canvas_sides;
  /// The seconds of frames `raster --bench` draws for the user's path (user_path.hpp).
  double user_path_budget_seconds = 0.1;
};

/// The settings of a suite size.
BenchSettings bench_settings(SuiteSize size);

}  // namespace tri::ch10
