#include "chapters/10_speed_vs_error/scaling.hpp"

#include <algorithm>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <utility>

#include "measure/child_process.hpp"
#include "measure/fill_ceiling.hpp"
#include "measure/process_memory.hpp"

namespace tri::ch10 {
namespace {

// The recipe of one scene kind of a suite size (tiny, mixed, large).
SuiteScene suite_scene(SuiteSize size, std::string_view kind) {
  for (const SuiteScene& scene : scene_suite(size)) {
    if (scene.name == kind && scene.grid == grid_label(8)) return scene;
  }
  throw std::invalid_argument("the suite has no scene kind '" + std::string(kind) + "'");
}

// What a child process answers: plain bytes.
struct ChildAnswer {
  Timing timing;
  std::uint64_t peak_bytes = 0;
};

// The faster of the two ceiling fills over the canvas of the scene: one frame that writes every
// pixel once and does nothing else.
Timing time_one_fill(const PreparedScene& prepared, const TimingPlan& plan) {
  Canvas canvas(prepared.scene.width, prepared.scene.height);
  const std::vector<Timing> timings = time_ceiling_fills(canvas, 1, plan);
  return *std::min_element(timings.begin(), timings.end(), [](const Timing& a, const Timing& b) {
    return a.seconds.median < b.seconds.median;
  });
}

// A point of the sweep with what the drawer and the scene say about themselves, not yet measured.
ScalingPoint unmeasured_point(const ScalingDrawer& drawer, const PreparedScene& prepared,
                              std::string_view sweep) {
  ScalingPoint point;
  point.sweep = sweep;
  point.drawer = drawer.name;
  point.chapter = drawer.chapter;
  point.scene = prepared.suite.name;
  point.side = prepared.scene.width;
  point.triangles = prepared.triangles.size();
  point.scene_bytes = prepared.triangles.size() * sizeof(SceneTriangle);
  return point;
}

std::string progress_line(const ScalingPoint& p) {
  char line[256];
  if (!p.measured) {
    std::snprintf(line, sizeof line, "[scaling] %-9s %-5s %5d² %9zu  %-24s not measured",
                  p.sweep.c_str(), p.scene.c_str(), p.side, p.triangles, p.drawer.c_str());
  } else {
    std::snprintf(line, sizeof line,
                  "[scaling] %-9s %-5s %5d² %9zu  %-24s %10.3f ms/frame  +%.1f MiB",
                  p.sweep.c_str(), p.scene.c_str(), p.side, p.triangles, p.drawer.c_str(),
                  p.timing.seconds.median * 1e3, static_cast<double>(p.peak_bytes) / (1 << 20));
  }
  return line;
}

}  // namespace

ScalingSettings scaling_settings(SuiteSize size) {
  ScalingSettings settings;
  switch (size) {
    case SuiteSize::tiny:
      settings.triangle_counts = {10, 100};
      settings.triangles_canvas_side = 32;
      settings.canvas_sides = {16, 32};
      settings.large_triangles = 2;
      settings.timing = {0.0, 1, 1};
      settings.frame_budget_seconds = 60;
      break;
    case SuiteSize::quick:
      settings.triangle_counts = {1000, 10000, 100000};
      settings.triangles_canvas_side = 256;
      settings.canvas_sides = {256, 512, 1024, 2048};
      settings.timing = {0.01, 3, 1 << 20};
      settings.frame_budget_seconds = 0.25;
      break;
    case SuiteSize::full:
      settings.triangle_counts = {1000, 10000, 100000, 1000000, 10000000};
      settings.triangles_canvas_side = 512;
      settings.canvas_sides = {256, 512, 1024, 2048, 4096, 8192, 16384};
      settings.timing = {0.02, 5, 1 << 22};
      settings.frame_budget_seconds = 3;
      break;
  }
  return settings;
}

SuiteScene triangles_sweep_scene(std::string_view kind, int count, int side) {
  // The suite of the canvas's size sets the extents: the full suite's on 512², else the quick's.
  SuiteScene scene = suite_scene(side >= 512 ? SuiteSize::full : SuiteSize::quick, kind);
  scene.recipe.width = scene.recipe.height = side;
  scene.recipe.triangles = count;
  return scene;
}

SuiteScene canvas_sweep_scene(int side, int triangles) {
  SuiteScene scene = suite_scene(SuiteSize::quick, "large");
  const double scale = static_cast<double>(side) / scene.recipe.width;
  scene.recipe.width = scene.recipe.height = side;
  scene.recipe.triangles = triangles;
  scene.recipe.min_extent *= scale;
  scene.recipe.max_extent *= scale;
  return scene;
}

std::vector<ScalingDrawer> scaling_drawers(std::span<const TriangleAlgorithm> algorithms,
                                           std::span<const ExternalPeer> peers) {
  std::vector<ScalingDrawer> drawers;
  const auto fastest =
      std::find_if(algorithms.begin(), algorithms.end(),
                   [](const TriangleAlgorithm& a) { return a.role == Role::cost_sweeps; });
  if (fastest != algorithms.end()) {
    drawers.push_back(
        {std::string(fastest->name), std::string(fastest->chapter), false,
         [algorithm = *fastest](const PreparedScene& prepared, const TimingPlan& plan) {
           return time_algorithms(std::span(&algorithm, 1), prepared, plan).front();
         }});
    drawers.push_back({"write_ceiling", "ceiling", true, time_one_fill});
  }
  for (const ExternalPeer& peer : peers) {
    if (peer.time) {
      drawers.push_back({std::string(peer.name), std::string(peer.chapter), false, peer.time});
    }
  }
  return drawers;
}

ScalingPoint measure_scaling_point(const ScalingDrawer& drawer, const PreparedScene& prepared,
                                   std::string_view sweep, const TimingPlan& plan) {
  ScalingPoint point = unmeasured_point(drawer, prepared, sweep);
  try {
    // [listing scaling_child]
    const ChildAnswer answer = run_in_child<ChildAnswer>([&] {
      // The child starts with the parent's pages, its peak with them: count what the draw adds,
      // and let nothing it allocates come from free memory that is resident already.
      release_free_heap();
      reset_peak_resident();
      const std::uint64_t before = resident_bytes();
      ChildAnswer a;
      a.timing = drawer.time(prepared, plan);
      a.peak_bytes = std::max(peak_resident_bytes(), before) - before;
      return a;
    });
    // [/listing]
    point.measured = true;
    point.timing = answer.timing;
    point.peak_bytes = answer.peak_bytes;
  } catch (const std::exception& e) {
    point.not_measured_because = e.what();
  }
  return point;
}

double swept_quantity(const ScalingPoint& point) noexcept {
  return point.sweep == "canvas" ? static_cast<double>(point.side) * point.side
                                 : static_cast<double>(point.triangles);
}

std::vector<ScalingPoint> run_scaling(std::span<const ScalingDrawer> drawers,
                                      const ScalingSettings& settings, std::ostream& progress) {
  std::vector<ScalingPoint> points;
  // Each drawer's last measured point of a sweep and scene, to predict the next one from.
  std::map<std::pair<std::string, std::string>, ScalingPoint> last_measured;
  const auto run_point = [&](const SuiteScene& suite, std::string_view sweep) {
    const PreparedScene prepared = prepare_scene(suite, 1);
    for (const ScalingDrawer& drawer : drawers) {
      if (drawer.canvas_sweep_only && sweep != "canvas") continue;
      const auto key = std::make_pair(std::string(sweep) + suite.name, drawer.name);
      ScalingPoint point = unmeasured_point(drawer, prepared, sweep);
      // [listing scaling_budget]
      // A frame is predicted to take as long as the last one, in proportion to what grew.
      const auto last = last_measured.find(key);
      const double predicted = last == last_measured.end()
                                   ? 0.0
                                   : last->second.timing.seconds.median * swept_quantity(point) /
                                         swept_quantity(last->second);
      // [/listing]
      if (predicted > settings.frame_budget_seconds) {
        char reason[200];
        std::snprintf(reason, sizeof reason,
                      "predicted %.2f s per frame (%.2f s at %zu triangles on %d², in proportion), "
                      "over the budget of %.2f s",
                      predicted, last->second.timing.seconds.median, last->second.triangles,
                      last->second.side, settings.frame_budget_seconds);
        point.not_measured_because = reason;
      } else {
        point = measure_scaling_point(drawer, prepared, sweep, settings.timing);
        if (point.measured) last_measured[key] = point;
      }
      progress << progress_line(point) << std::endl;  // flushed: the line is the progress
      points.push_back(std::move(point));
    }
  };
  for (const std::string_view kind : {"tiny", "mixed"}) {
    for (const int count : settings.triangle_counts) {
      run_point(triangles_sweep_scene(kind, count, settings.triangles_canvas_side), "triangles");
    }
  }
  for (const int side : settings.canvas_sides) {
    run_point(canvas_sweep_scene(side, settings.large_triangles), "canvas");
  }
  return points;
}

}  // namespace tri::ch10
