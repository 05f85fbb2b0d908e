// Chapter 08's speed table: the chapter's variants, chapter 07's fixed_point_8 and chapter 06's
// barycentric_double on the scenes the chapter's targets name, beside the write ceiling of the
// same canvas (the faster of memset and vector stores, measure/fill_ceiling.hpp) measured in the
// same rounds. Timed with the book's one method (measure/timing.hpp,
// docs/DESIGN.md section 8): warm-up, calibrated repetitions, interleaved rounds, median and
// spread on the steady clock.
#include <algorithm>
#include <array>
#include <cstdint>
#include <ctime>
#include <functional>
#include <iomanip>
#include <iostream>
#include <numeric>
#include <optional>
#include <span>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "chapters/08_fast_exact/algorithms.hpp"
#include "chapters/08_fast_exact/batched.hpp"
#include "chapters/08_fast_exact/narrow_canvases.hpp"
#include "chapters/08_fast_exact/pixel_writers.hpp"
#include "chapters/08_fast_exact/threaded.hpp"
#include "chapters/08_fast_exact/tiled.hpp"
#include "common/cli.hpp"
#include "common/printable_text.hpp"
#include "common/progress.hpp"
#include "measure/drawable.hpp"
#include "measure/fill_ceiling.hpp"
#include "measure/registry.hpp"
#include "measure/render_scene.hpp"
#include "measure/scene_generators.hpp"
#include "measure/timing.hpp"

namespace {

using tri::Canvas;
using tri::SceneTriangle;
using tri::Timing;
using tri::TimingPlan;
using tri::TriangleAlgorithm;

constexpr int canvas_side = 512;             // every scene's canvas but the one large-canvas scene
constexpr int large_canvas_side = 4096;      // 64 MiB of pixels: far beyond any cache
constexpr double min_sample_seconds = 0.03;  // one sample of a variant: about 30 ms of draws

// What the command line asks for, checked before anything is measured.
struct Options {
  int repeats = 7;                  // timed samples (rounds) per measurement
  std::string scene_filter;         // only scenes whose name contains this
  std::optional<long long> frames;  // draws per sample, fixed; none: calibrated
  bool probes = false;              // only the two-thread probes
  bool force = false;
  std::vector<std::string> algorithm_names;
};

struct BenchScene {
  std::string name;
  int side = canvas_side;  // the square canvas it is drawn on
  std::vector<SceneTriangle> triangles;
  tri::PreparedBatch batch;  // the triangles checked once: what the timed draws take
};

// The scene a recipe describes on a square canvas, every vertex on the 1/256 grid.
BenchScene bench_scene(std::string name, tri::SceneRecipe recipe, int side = canvas_side) {
  recipe.width = recipe.height = side;
  recipe.grid_bits = 8;
  std::vector<SceneTriangle> triangles = tri::scene_triangles(tri::generate_scene(recipe));
  tri::PreparedBatch batch(triangles);
  return {std::move(name), side, std::move(triangles), std::move(batch)};
}

tri::SceneRecipe random_recipe(int triangles, double min_extent, double max_extent,
                               std::uint64_t seed) {
  tri::SceneRecipe recipe;
  recipe.triangles = triangles;
  recipe.min_extent = min_extent;
  recipe.max_extent = max_extent;
  recipe.seed = seed;
  return recipe;
}

std::vector<BenchScene> bench_scenes() {
  using Kind = tri::SceneRecipe::Kind;
  std::vector<BenchScene> scenes;
  tri::SceneRecipe large = random_recipe(200, 255, 255, 1);
  large.min_area = 10000;
  scenes.push_back(bench_scene("large (area >= 10000)", large));
  // The same kind of scene scaled 8x, on a canvas that no cache holds.
  tri::SceneRecipe large_canvas = random_recipe(200, 2040, 2040, 5);
  large_canvas.min_area = 640000;
  scenes.push_back(
      bench_scene("large on 4096x4096 (area >= 640000)", large_canvas, large_canvas_side));
  tri::SceneRecipe tiny = random_recipe(100000, 3, 3, 2);
  tiny.min_area = 1;
  tiny.max_area = 10;
  scenes.push_back(bench_scene("tiny (area 1-10)", tiny));
  // The same scene as chapter 10's --full "mesh" on the 1/256 grid (224x224 cells, seed 9012),
  // so the two programs can be checked against each other.
  tri::SceneRecipe mesh = random_recipe(100352, 0, 0, 9012);
  mesh.kind = Kind::jittered_grid;
  scenes.push_back(bench_scene("jittered-grid mesh", mesh));
  scenes.push_back(bench_scene("random mixed (extent 1-100)", random_recipe(10000, 1, 100, 3)));
  tri::SceneRecipe slivers = random_recipe(10000, 10, 200, 4);
  slivers.kind = Kind::slivers;
  scenes.push_back(bench_scene("slivers (length 10-200)", slivers));
  return scenes;
}

// The registry's speed baseline and the exact algorithm chapter 08 starts from (their declared
// roles), then every chapter 08 variant.
std::vector<TriangleAlgorithm> compared_algorithms() {
  std::vector<TriangleAlgorithm> algorithms;
  for (const auto& a : tri::registered_algorithms()) {
    if (a.role == tri::Role::speed_baseline || a.role == tri::Role::fast_exact_starting) {
      algorithms.push_back(a);
    }
  }
  for (const auto& a : tri::ch08::triangle_algorithms()) {
    if (tri::find_named(algorithms, a.name) == nullptr) algorithms.push_back(a);
  }
  return algorithms;
}

// Names and scenes are checked before anything is measured: a typo is an error, not a table
// without rows.
Options options_from(const tri::CliArguments& args,
                     const std::vector<TriangleAlgorithm>& algorithms,
                     const std::vector<BenchScene>& scenes) {
  Options options;
  options.repeats = static_cast<int>(args.integer("repeats", 1, 1000).value_or(7));
  options.scene_filter = args.value_or("scene", "");
  options.frames = args.integer("frames", 1, 1000000);
  options.probes = args.has("probes");
  options.force = args.has("force");
  for (const auto& a : algorithms) options.algorithm_names.emplace_back(a.name);
  if (const auto list = args.value("algos")) {
    options.algorithm_names = tri::parse_name_list("algos", *list, options.algorithm_names);
  }
  if (std::none_of(scenes.begin(), scenes.end(), [&](const BenchScene& scene) {
        return scene.name.find(options.scene_filter) != std::string::npos;
      })) {
    std::string choices;
    for (const auto& scene : scenes) choices += (choices.empty() ? "" : "; ") + scene.name;
    throw tri::UsageError("--scene '" + tri::printable_excerpt(options.scene_filter) +
                          "' matches no scene (the scenes: " + choices + ")");
  }
  return options;
}

TimingPlan timing_plan(const Options& options) {
  TimingPlan plan;
  plan.min_sample_seconds = min_sample_seconds;
  plan.samples = options.repeats;
  plan.max_repetitions = 100000;
  plan.repetitions = static_cast<int>(options.frames.value_or(0));
  return plan;
}

// The algorithms the options name, in the table's order.
std::vector<const TriangleAlgorithm*> selected(const std::vector<TriangleAlgorithm>& algorithms,
                                               const Options& options) {
  std::vector<const TriangleAlgorithm*> chosen;
  for (const TriangleAlgorithm& algorithm : algorithms) {
    const auto& names = options.algorithm_names;
    if (std::find(names.begin(), names.end(), algorithm.name) != names.end())
      chosen.push_back(&algorithm);
  }
  return chosen;
}

// The timed work, kept out of line so a profiler can single it out
// (valgrind --tool=callgrind --toggle-collect='*timed_draw*').
[[gnu::noinline]] void timed_draw(tri::BatchDrawer& drawer, Canvas& canvas,
                                  const tri::PreparedBatch& batch) {
  drawer.draw(canvas, batch);
}

std::uint64_t covered_pixels(const TriangleAlgorithm& algorithm, const BenchScene& scene) {
  Canvas canvas(scene.side, scene.side);
  canvas.enable_write_counts();
  tri::draw_triangles(algorithm, canvas, scene.triangles);
  const auto counts = canvas.write_counts();
  return std::accumulate(counts.begin(), counts.end(), std::uint64_t{0});
}

// What one scene's rounds time: the ceiling's two fills first, then one draw per algorithm, each
// through its drawer in `drawers` (made by the caller before the clock runs, one per algorithm).
std::vector<std::function<void()>> scene_runs(const BenchScene& scene,
                                              std::vector<tri::BatchDrawer>& drawers,
                                              Canvas& canvas) {
  std::vector<std::function<void()>> runs;
  for (const tri::CeilingFill fill : tri::ceiling_fills)
    runs.push_back(tri::ceiling_fill_run(canvas, fill, 1));
  for (tri::BatchDrawer& drawer : drawers)
    runs.emplace_back([&canvas, &scene, &drawer] { timed_draw(drawer, canvas, scene.batch); });
  return runs;
}

// Whether the algorithm declares step 8's narrow canvases among its outputs.
bool draws_narrow_formats(const TriangleAlgorithm* algorithm) {
  return algorithm->outputs.has(tri::Output::index8) && algorithm->outputs.has(tri::Output::mask1);
}

// Step 8's narrow canvases of the scene's size, drawn by fast_spans beside the RGBA8 rows.
struct NarrowCanvases {
  tri::ch08::IndexCanvas index;
  tri::ch08::MaskCanvas mask;
};

// fast_spans into one byte per pixel (indices 1 to 255 in turn) and into one bit per pixel.
void add_narrow_runs(const BenchScene& scene, NarrowCanvases& narrow,
                     std::vector<std::function<void()>>& runs) {
  runs.emplace_back([&scene, &narrow] {
    for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
      tri::ch08::draw_triangle_spans_index8(narrow.index, scene.triangles[i].vertices,
                                            static_cast<std::uint8_t>(1 + i % 255));
    }
  });
  runs.emplace_back([&scene, &narrow] {
    for (const SceneTriangle& t : scene.triangles)
      tri::ch08::draw_triangle_spans_mask1(narrow.mask, t.vertices);
  });
}

// One draw of each run tells how long the rounds will take: an absurd estimate is refused.
void refuse_absurd_scene(const BenchScene& scene, const std::vector<std::function<void()>>& runs,
                         const TimingPlan& plan, bool forced) {
  double estimate = 0;
  for (const auto& run : runs) {
    const double once = tri::seconds_of(run);
    const double sample =
        plan.repetitions > 0 ? once * plan.repetitions : std::max(once, plan.min_sample_seconds);
    estimate += once + 2 * sample + sample * plan.samples;  // warm-up, calibration, rounds
  }
  tri::refuse_absurd_run(estimate, "the " + scene.name + " scene", forced);
}

std::vector<Timing> time_scene(const BenchScene& scene,
                               const std::vector<std::function<void()>>& runs,
                               const TimingPlan& plan) {
  tri::Progress progress("08_fast_exact_bench: " + scene.name,
                         static_cast<std::uint64_t>(plan.samples), std::cerr);
  return tri::time_interleaved(
      runs, plan, [&](int rounds) { progress.advance(static_cast<std::uint64_t>(rounds)); });
}

// The speed column divides by the time of the algorithm whose declared role is the baseline.
void print_table_header(std::span<const TriangleAlgorithm> algorithms, std::ostream& out) {
  const TriangleAlgorithm* baseline =
      tri::algorithm_with_role(algorithms, tri::Role::speed_baseline);
  out << "| scene | algorithm | Mtriangles/s | Mpixels/s | × `"
      << (baseline != nullptr ? baseline->name : std::string_view("baseline"))
      << "` | % of ceiling | ms per draw: median (min-max) |\n"
         "|---|---|---:|---:|---:|---:|---:|\n";
}

std::string milliseconds(const tri::Spread& seconds) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(3) << 1e3 * seconds.median << " (" << 1e3 * seconds.min
       << "-" << 1e3 * seconds.max << ")";
  return text.str();
}

// The rows of step 8's narrow canvases, when fast_spans was timed: the same pixels as its RGBA8
// row, fewer bytes per pixel. No % of ceiling: the ceiling is for 4 bytes per pixel.
void print_narrow_rows(const BenchScene& scene, const std::vector<const TriangleAlgorithm*>& timed,
                       const std::vector<Timing>& timings, double baseline, std::ostream& out) {
  const auto spans = std::find_if(timed.begin(), timed.end(), draws_narrow_formats);
  if (spans == timed.end()) return;
  const double pixels = static_cast<double>(covered_pixels(**spans, scene));
  const double triangles = static_cast<double>(scene.triangles.size());
  const std::array<const char*, 2> formats{"1 byte", "1 bit"};
  for (std::size_t k = 0; k < formats.size(); ++k) {
    const tri::Spread& seconds = timings[2 + timed.size() + k].seconds;
    out << "|  | `" << (*spans)->name << "`, " << formats[k] << " per pixel | " << std::defaultfloat
        << std::setprecision(3) << triangles / seconds.median / 1e6 << " | " << std::fixed
        << std::setprecision(0) << tri::mpix_per_second(pixels, seconds.median) << " | ";
    if (baseline > 0) out << std::setprecision(1) << baseline / seconds.median;
    out << " | | " << milliseconds(seconds) << " |\n";
  }
}

// The rows of one scene: the ceiling's two fills, then one row per algorithm. timings holds the
// fills first, as scene_runs made them.
void print_scene_rows(const BenchScene& scene, const std::vector<const TriangleAlgorithm*>& timed,
                      const std::vector<Timing>& timings, std::ostream& out) {
  const double pixels_per_canvas = static_cast<double>(scene.side) * scene.side;
  const tri::FillCeiling ceiling = tri::fill_ceiling_of(pixels_per_canvas, timings[0], timings[1]);
  out << "| " << scene.name << " | (ceiling: `memset`; vector stores) | | " << std::fixed
      << std::setprecision(0) << ceiling.memset_mpix_per_s << "; "
      << ceiling.vector_stores_mpix_per_s << " | | 100 | " << milliseconds(timings[0].seconds)
      << "; " << milliseconds(timings[1].seconds) << " |\n";
  double baseline = 0;
  const double triangles = static_cast<double>(scene.triangles.size());
  for (std::size_t i = 0; i < timed.size(); ++i) {
    const TriangleAlgorithm& algorithm = *timed[i];
    const tri::Spread& seconds = timings[i + 2].seconds;
    if (algorithm.role == tri::Role::speed_baseline) baseline = seconds.median;
    const double pixel_rate =
        tri::mpix_per_second(static_cast<double>(covered_pixels(algorithm, scene)), seconds.median);
    out << "|  | `" << algorithm.name << "`" << (algorithm.threaded ? " (threads)" : "") << " | "
        << std::defaultfloat << std::setprecision(3) << triangles / seconds.median / 1e6 << " | "
        << std::fixed << std::setprecision(0) << pixel_rate << " | ";
    if (baseline > 0) out << std::setprecision(1) << baseline / seconds.median;
    out << " | " << std::setprecision(0) << 100 * pixel_rate / ceiling.mpix_per_s() << " | "
        << milliseconds(seconds) << " |\n";
  }
  print_narrow_rows(scene, timed, timings, baseline, out);
  out.flush();
}

void benchmark_scene(const BenchScene& scene, const std::vector<const TriangleAlgorithm*>& timed,
                     const Options& options, std::ostream& out) {
  Canvas canvas(scene.side, scene.side);
  NarrowCanvases narrow{{scene.side, scene.side}, {scene.side, scene.side}};
  const TimingPlan plan = timing_plan(options);
  // Kept for every draw of the scene: a renderer's threads start here, not in the rounds.
  std::vector<tri::BatchDrawer> drawers;
  for (const TriangleAlgorithm* algorithm : timed) drawers.emplace_back(*algorithm);
  std::vector<std::function<void()>> runs = scene_runs(scene, drawers, canvas);
  if (std::any_of(timed.begin(), timed.end(), draws_narrow_formats)) {
    add_narrow_runs(scene, narrow, runs);
  }
  refuse_absurd_scene(scene, runs, plan, options.force);
  print_scene_rows(scene, timed, time_scene(scene, runs, plan), out);
}

// The median of `alone` over the median of `together`, timed against each other in rounds.
double speedup(const std::function<void()>& alone, const std::function<void()>& together,
               const TimingPlan& plan) {
  const std::vector<std::function<void()>> runs{alone, together};
  const std::vector<Timing> timings = tri::time_interleaved(runs, plan);
  return timings[0].seconds.median / timings[1].seconds.median;
}

// What two threads gain on plain stores: each fills the rows of its own bands of the canvas (the
// bands fast_threaded uses) with fill_pixels, against one thread filling all of them. This is the
// ceiling of fast_threaded on large triangles.
double two_thread_fill_speedup(Canvas& canvas, const TimingPlan& plan) {
  const tri::ch08::Bands bands = tri::ch08::bands_for(canvas.height(), 2);
  // 200 fills per thread start, so starting the thread is not what is measured.
  const auto fill_rows = [&](int thread, int threads) {
    for (int frame = 0; frame < 200; ++frame) {
      for (int y = 0; y < canvas.height(); ++y) {
        if (threads == 1 || bands.owner(y) == thread)
          tri::ch08::fill_pixels(canvas.row(y).data(), canvas.width(), 0u);
      }
    }
  };
  return speedup([&] { fill_rows(0, 1); },
                 [&] {
                   std::jthread helper([&] { fill_rows(1, 2); });
                   fill_rows(0, 2);
                 },
                 plan);
}

// What two threads gain on arithmetic alone: a chain of integer multiplications and shifts, split
// in halves, against one thread doing all of it.
double two_thread_arithmetic_speedup(const TimingPlan& plan) {
  const auto work = [](long steps) {
    std::uint64_t a = 1, b = 2;
    for (long i = 0; i < steps; ++i) {
      a = a * 3 + b;
      b ^= a >> 3;
    }
    return a + b;
  };
  constexpr long steps = 2'000'000;
  std::uint64_t sink = 0;  // keeps the work from being optimized away
  const double gain = speedup([&] { sink += work(steps); },
                              [&] {
                                std::uint64_t other = 0;
                                {
                                  std::jthread helper([&] { other = work(steps / 2); });
                                  sink += work(steps / 2);
                                }
                                sink += other;
                              },
                              plan);
  return sink == 0 ? 0 : gain;
}

// fast_threaded on a scene with two threads against one (the same code with one thread), and
// each thread's share drawn alone on the calling thread, which shows how evenly the bands split
// the work: all five timed against each other in rounds.
void threaded_probe(const BenchScene& scene, Canvas& canvas, const TimingPlan& plan,
                    std::ostream& out) {
  const auto on_threads = [&](int threads) {
    return [&canvas, &scene, threads] {
      tri::ch08::draw_batch_on_threads(canvas, scene.triangles, threads);
    };
  };
  const auto share = [&](int thread, int threads) {
    return [&canvas, &scene, thread, threads] {
      tri::ch08::draw_bands_of_thread(canvas, scene.triangles, thread, threads);
    };
  };
  const std::vector<std::function<void()>> runs{on_threads(1), on_threads(2), share(0, 1),
                                                share(0, 2), share(1, 2)};
  const std::vector<Timing> t = tri::time_interleaved(runs, plan);
  const double whole = t[2].seconds.median, first = t[3].seconds.median,
               second = t[4].seconds.median;
  out << "fast_threaded on the " << scene.name << " scene: two threads " << std::fixed
      << std::setprecision(2) << t[0].seconds.median / t[1].seconds.median
      << "x the speed of one; each thread's share drawn alone takes " << 100 * first / whole
      << "% and " << 100 * second / whole << "% of the serial draw, an ideal speed-up of "
      << whole / std::max(first, second) << "\n";
}

// fast_tiled_threaded on a scene with two threads against one: a TiledRenderer of each, kept
// for every draw (threads and bins made once), timed against each other in rounds, and beside them
// fast_batched, the fastest single-thread variant on the mesh. Beside the wall clock, the
// process's CPU time per draw: another process taking a core does not inflate it, so two threads
// together near the CPU time of one means the work was split without adding any, whatever the wall
// clock saw.
void tiled_probe(const BenchScene& scene, const TimingPlan& plan, std::ostream& out) {
  Canvas canvas(scene.side, scene.side);
  std::array<tri::ch08::TiledRenderer, 2> renderers{tri::ch08::TiledRenderer(1),
                                                    tri::ch08::TiledRenderer(2)};
  std::array<std::vector<double>, 3> cpu;
  const auto timed = [&cpu](std::size_t k, auto draw) {
    return [&cpu, k, draw] {
      const std::clock_t start = std::clock();
      draw();
      cpu[k].push_back(static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC);
    };
  };
  const auto on_threads = [&](int threads) {
    auto& renderer = renderers[static_cast<std::size_t>(threads - 1)];
    return timed(static_cast<std::size_t>(threads - 1),
                 [&canvas, &scene, &renderer] { renderer.draw(canvas, scene.triangles); });
  };
  const auto batched =
      timed(2, [&canvas, &scene] { tri::ch08::draw_batch_batched(canvas, scene.triangles); });
  const std::vector<std::function<void()>> runs{on_threads(1), on_threads(2), batched};
  const std::vector<Timing> t = tri::time_interleaved(runs, plan);
  const double one = tri::spread_of(cpu[0]).median, two = tri::spread_of(cpu[1]).median;
  out << "fast_tiled_threaded on the " << scene.name << " scene: two threads " << std::fixed
      << std::setprecision(2) << t[0].seconds.median / t[1].seconds.median << "x the speed of one, "
      << t[2].seconds.median / t[1].seconds.median << "x fast_batched's; CPU time per draw "
      << std::setprecision(3) << 1e3 * one << " ms on one thread, " << 1e3 * two
      << " ms on two together (" << std::setprecision(0) << 100 * two / one << "%), fast_batched "
      << std::setprecision(3) << 1e3 * tri::spread_of(cpu[2]).median << " ms\n";
}

void print_probes(const std::vector<BenchScene>& scenes, Canvas& canvas, const Options& options,
                  std::ostream& out) {
  const BenchScene& large = scenes.front();
  TimingPlan plan = timing_plan(options);
  plan.repetitions = 0;  // always calibrated: the probes' work differs in length
  out << "\nTwo threads filling their own bands of the canvas with fill_pixels: " << std::fixed
      << std::setprecision(2) << two_thread_fill_speedup(canvas, plan)
      << "x the speed of one thread\n";
  out << "Two threads sharing integer arithmetic: " << two_thread_arithmetic_speedup(plan)
      << "x the speed of one thread\n";
  threaded_probe(large, canvas, plan, out);
  for (const BenchScene& scene : scenes) {
    if (scene.name.starts_with("large") || scene.name.starts_with("jittered"))
      tiled_probe(scene, plan, out);
  }
}

int run(const tri::CliArguments& args, std::ostream& out) {
  const std::vector<TriangleAlgorithm> algorithms = compared_algorithms();
  const std::vector<BenchScene> scenes = bench_scenes();
  const Options options = options_from(args, algorithms, scenes);
  const std::vector<const TriangleAlgorithm*> timed = selected(algorithms, options);
  bool header_written = false;  // written with the first rows, so a refused run prints no table
  for (const BenchScene& scene : scenes) {
    if (options.probes || scene.name.find(options.scene_filter) == std::string::npos) continue;
    if (!header_written) print_table_header(algorithms, out);
    header_written = true;
    benchmark_scene(scene, timed, options, out);
  }
  if (options.scene_filter.empty() || options.probes) {
    Canvas canvas(canvas_side, canvas_side);
    print_probes(scenes, canvas, options, out);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const tri::CommandLine command_line(
      "08_fast_exact_bench",
      "Times chapter 08's variants (and fixed_point_8, barycentric_double) on large, tiny, mesh,\n"
      "mixed and sliver scenes of a 512x512 canvas and on large triangles of a 4096x4096 one,\n"
      "beside the write ceiling of the canvas (the faster of memset and vector stores),\n"
      "all in interleaved rounds on the steady clock. Prints a Markdown table of medians with\n"
      "their spread. Build in Release; run on an otherwise idle machine.",
      {{"repeats", "N", "timed rounds per measurement, the median is printed (default 7)"},
       {"algos", "A,B", "only these algorithms (comma-separated names)"},
       {"scene", "TEXT", "only the scenes whose name contains TEXT (e.g. tiny, mesh)"},
       {"frames", "N", "draw each scene N times per timed sample (default: about 30 ms worth)"},
       {"probes", "", "only the two-thread probes: fills, arithmetic, bands and tiles"},
       {"force", "", "measure even when the estimated time exceeds 10 minutes"}});
  return tri::run_command_line(command_line, argc, argv, std::cout, std::cerr,
                               [&](const tri::CliArguments& args) { return run(args, std::cout); });
}
