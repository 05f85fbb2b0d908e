/// @file
/// How the cost of a frame grows: the report's two sweeps. Time per frame against the number of
/// triangles (the suite's tiny and mixed scenes, 10^3 to 10^7 triangles) and against the canvas
/// (its large scene scaled, 256² to 16384²), with the peak memory each draw adds, for the fastest
/// exact algorithm and the external peers.
#pragma once

#include <cstdint>
#include <functional>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "chapters/10_speed_vs_error/measure.hpp"
#include "chapters/10_speed_vs_error/suites.hpp"

namespace tri::ch10 {

/// The points of both sweeps at one suite size.
struct ScalingSettings {
  std::vector<int> triangle_counts;  ///< the triangles sweep, on the tiny and the mixed scene
  int triangles_canvas_side = 256;   ///< the triangles sweep's canvas (the suite's)
  std::vector<int> canvas_sides;     ///< the canvas sweep, on the large scene
  int large_triangles = 16;          ///< triangles of every canvas-sweep scene
  TimingPlan timing;
  /// A drawer is not timed where its frame would take longer than this, predicted from its last
  /// measured point of the sweep and scene in proportion (the report says so), so a slow peer
  /// cannot take an hour.
  double frame_budget_seconds = 1;
};

/// The sweeps of a suite size: quick stops at 10^5 triangles and 2048², full goes to 10^7 and
/// 16384².
ScalingSettings scaling_settings(SuiteSize size);

/// The suite's tiny or mixed scene kind with `count` triangles on a side x side canvas, 1/256 grid.
SuiteScene triangles_sweep_scene(std::string_view kind, int count, int side);

/// The quick suite's large scene (extents a quarter to five eighths of the side) on a side x side
/// canvas, 1/256 grid.
SuiteScene canvas_sweep_scene(int side, int triangles);

/// Something the sweeps time.
struct ScalingDrawer {
  std::string name;
  std::string chapter;  ///< the chapter folder, "external" for a peer, "ceiling" for the fill
  bool canvas_sweep_only = false;
  /// Seconds per draw of the prepared scene, its canvas and inputs made before the clock. Called
  /// in a child process of its own (run_scaling), so it may start libraries that keep threads.
  std::function<Timing(const PreparedScene&, const TimingPlan&)> time;
};

/// The algorithm whose declared role is Role::cost_sweeps (the fastest exact one of chapter 08)
/// when it is among `algorithms`, the write ceiling (one fill of the canvas,
/// the faster of memset and vector stores) when any is, then every peer that can time a draw.
std::vector<ScalingDrawer> scaling_drawers(std::span<const TriangleAlgorithm> algorithms,
                                           std::span<const ExternalPeer> peers);

/// One drawer at one point of a sweep.
struct ScalingPoint {
  std::string sweep;  ///< "triangles" or "canvas"
  std::string drawer;
  std::string chapter;
  std::string scene;  ///< tiny, mixed or large
  int side = 0;       ///< the square canvas's side
  std::size_t triangles = 0;
  std::uint64_t scene_bytes = 0;  ///< the triangle list every drawer is given
  bool measured = false;
  std::string not_measured_because;
  Timing timing;                 ///< seconds per frame
  std::uint64_t peak_bytes = 0;  ///< resident memory the draw added at its peak: canvas, copies
};

/// What a sweep grows: the triangles, or the canvas's pixels.
double swept_quantity(const ScalingPoint& point) noexcept;

/// Times the drawer on the prepared scene in a child process and reads the child's peak resident
/// memory above what it held when it started (the scene is the parent's, shared, not counted).
ScalingPoint measure_scaling_point(const ScalingDrawer& drawer, const PreparedScene& prepared,
                                   std::string_view sweep, const TimingPlan& plan);

/// Both sweeps, every drawer at every point (each scene generated once), one progress line per
/// point.
std::vector<ScalingPoint> run_scaling(std::span<const ScalingDrawer> drawers,
                                      const ScalingSettings& settings, std::ostream& progress);

}  // namespace tri::ch10
