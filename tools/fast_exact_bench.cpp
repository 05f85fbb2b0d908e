// Chapter 08's speed table: the chapter's variants, chapter 07's fixed_point_8 and chapter 06's
// barycentric_double on the scenes the chapter's targets name, beside the std::fill rate of the
// same canvas measured in the same rounds. Medians of repeated timed runs, interleaved, from the
// thread's CPU time (the wall clock for the threaded variant).
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <ctime>
#include <functional>
#include <iomanip>
#include <iostream>
#include <numeric>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "chapters/08_fast_exact/algorithms.hpp"
#include "chapters/08_fast_exact/pixel_writers.hpp"
#include "chapters/08_fast_exact/threaded.hpp"
#include "common/cli.hpp"
#include "common/printable_text.hpp"
#include "common/progress.hpp"
#include "common/random.hpp"
#include "measure/registry.hpp"
#include "measure/scene_generators.hpp"

namespace {

using tri::Canvas;
using tri::SceneTriangle;
using tri::TriangleAlgorithm;
using Clock = std::chrono::steady_clock;

constexpr int canvas_side = 512;

struct BenchScene {
  std::string name;
  std::vector<SceneTriangle> triangles;
};

double grid(double v) {
  return tri::snap_to_grid(v, 8);
}

double doubled_area(const tri::Triangle& t) {
  return (t[1].x - t[0].x) * (t[2].y - t[0].y) - (t[1].y - t[0].y) * (t[2].x - t[0].x);
}

tri::Color random_color(tri::Random& random) {
  return {static_cast<std::uint8_t>(random.integer(64, 255)),
          static_cast<std::uint8_t>(random.integer(64, 255)),
          static_cast<std::uint8_t>(random.integer(64, 255)), 255};
}

// Triangles with vertices anywhere on the canvas whose area lies in [min_area, max_area], found
// by drawing vertices within `extent` of a random centre and keeping the ones that qualify.
std::vector<SceneTriangle> triangles_by_area(int count, double extent, double min_area,
                                             double max_area, std::uint64_t seed) {
  tri::Random random(seed);
  std::vector<SceneTriangle> triangles;
  while (static_cast<int>(triangles.size()) < count) {
    const double cx = random.real(extent, canvas_side - extent);
    const double cy = random.real(extent, canvas_side - extent);
    tri::Triangle t;
    for (auto& v : t) {
      v = {grid(cx + random.real(-extent, extent)), grid(cy + random.real(-extent, extent))};
    }
    const double area = std::abs(doubled_area(t)) / 2;
    if (area >= min_area && area <= max_area) triangles.push_back({t, random_color(random)});
  }
  return triangles;
}

std::vector<SceneTriangle> generated(tri::SceneRecipe recipe) {
  recipe.width = recipe.height = canvas_side;
  const tri::Scene scene = tri::generate_scene(recipe);
  std::vector<SceneTriangle> triangles;
  for (const auto& p : scene.primitives) triangles.push_back(std::get<SceneTriangle>(p));
  return triangles;
}

std::vector<BenchScene> bench_scenes() {
  using Kind = tri::SceneRecipe::Kind;
  std::vector<BenchScene> scenes;
  scenes.push_back({"large (area >= 10000)", triangles_by_area(200, 255, 10000, 1e9, 1)});
  scenes.push_back({"tiny (area 1-10)", triangles_by_area(100000, 3, 1, 10, 2)});
  tri::SceneRecipe mesh;
  mesh.kind = Kind::jittered_grid;
  mesh.triangles = 100000;
  scenes.push_back({"jittered-grid mesh", generated(mesh)});
  tri::SceneRecipe mixed;
  mixed.triangles = 10000;
  mixed.min_extent = 1;
  mixed.max_extent = 100;
  mixed.seed = 3;
  scenes.push_back({"random mixed (extent 1-100)", generated(mixed)});
  tri::SceneRecipe slivers;
  slivers.kind = Kind::slivers;
  slivers.triangles = 10000;
  slivers.min_extent = 10;
  slivers.max_extent = 200;
  slivers.seed = 4;
  scenes.push_back({"slivers (length 10-200)", generated(slivers)});
  return scenes;
}

// CPU time of the calling thread: unlike wall time it does not count the moments another
// process had the core, which matters on a shared machine.
double thread_cpu_seconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

// One thing to time: a name, the work of one call, and how many calls a timed run makes.
struct Measurable {
  Measurable(std::string name_, std::function<void()> run_, bool threaded_ = false)
      : name(std::move(name_)), run(std::move(run_)), threaded(threaded_) {}
  std::string name;
  std::function<void()> run;
  bool threaded;
  int frames = 1;
  std::vector<double> wall, cpu;  // seconds per call, one entry per round
};

// The wall time of one call.
double seconds_of_one_call(const std::function<void()>& run) {
  const auto start = Clock::now();
  run();
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Enough calls for about 30 ms per timed run, for a call that took `once` seconds.
int frames_for(double once) {
  return std::clamp(static_cast<int>(0.03 / std::max(once, 1e-9)), 1, 100000);
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

// Times every measurable once per round, round after round, so that whatever else the machine
// does slows them all alike; keeps each one's seconds per call by both clocks.
void measure_in_rounds(std::vector<Measurable>& measurables, int rounds, tri::Progress& progress) {
  for (Measurable& m : measurables) m.run();  // warm-up
  for (int r = 0; r < rounds; ++r) {
    progress.advance(static_cast<std::uint64_t>(r));
    for (Measurable& m : measurables) {
      const auto start = Clock::now();
      const double cpu_start = thread_cpu_seconds();
      for (int f = 0; f < m.frames; ++f) m.run();
      m.cpu.push_back((thread_cpu_seconds() - cpu_start) / m.frames);
      m.wall.push_back(std::chrono::duration<double>(Clock::now() - start).count() / m.frames);
    }
  }
}

// The timed work, kept out of line so a profiler can single it out
// (valgrind --tool=callgrind --toggle-collect='*timed_draw*').
[[gnu::noinline]] void timed_draw(const TriangleAlgorithm& algorithm, Canvas& canvas,
                                  const std::vector<SceneTriangle>& triangles) {
  tri::draw_triangles(algorithm, canvas, triangles);
}

std::uint64_t covered_pixels(const TriangleAlgorithm& algorithm,
                             const std::vector<SceneTriangle>& triangles) {
  Canvas canvas(canvas_side, canvas_side);
  canvas.enable_write_counts();
  tri::draw_triangles(algorithm, canvas, triangles);
  const auto counts = canvas.write_counts();
  return std::accumulate(counts.begin(), counts.end(), std::uint64_t{0});
}

// What two threads gain on plain stores: each fills the rows of its own bands of the canvas (the
// bands fast_threaded uses) with fill_pixels, against one thread filling all of them. Wall clock,
// median over rounds. This is the ceiling of fast_threaded on large triangles.
double two_thread_fill_speedup(Canvas& canvas, int rounds) {
  const tri::ch08::Bands bands = tri::ch08::bands_for(canvas.height(), 2);
  const std::array<std::uint32_t, 8> words{};
  const auto fill_rows = [&](int thread, int threads) {
    for (int frame = 0; frame < 200; ++frame) {
      for (int y = 0; y < canvas.height(); ++y) {
        if (threads == 1 || bands.owner(y) == thread)
          tri::ch08::fill_pixels(canvas.row(y).data(), canvas.width(), words);
      }
    }
  };
  std::vector<double> speedups;
  for (int r = 0; r < rounds; ++r) {
    auto start = Clock::now();
    fill_rows(0, 1);
    const double one = std::chrono::duration<double>(Clock::now() - start).count();
    start = Clock::now();
    {
      std::jthread helper([&] { fill_rows(1, 2); });
      fill_rows(0, 2);
    }
    speedups.push_back(one / std::chrono::duration<double>(Clock::now() - start).count());
  }
  return median(speedups);
}

// What two threads gain on arithmetic alone: a chain of integer multiplications and shifts, split
// in halves, against one thread doing all of it. Wall clock, median over rounds.
double two_thread_arithmetic_speedup(int rounds) {
  const auto work = [](long steps) {
    std::uint64_t a = 1, b = 2;
    for (long i = 0; i < steps; ++i) {
      a = a * 3 + b;
      b ^= a >> 3;
    }
    return a + b;
  };
  constexpr long steps = 20'000'000;
  std::vector<double> speedups;
  std::uint64_t sink = 0;
  for (int r = 0; r < rounds; ++r) {
    auto start = Clock::now();
    sink += work(steps);
    const double one = std::chrono::duration<double>(Clock::now() - start).count();
    start = Clock::now();
    std::uint64_t other = 0;
    {
      std::jthread helper([&] { other = work(steps / 2); });
      sink += work(steps / 2);
    }
    sink += other;
    speedups.push_back(one / std::chrono::duration<double>(Clock::now() - start).count());
  }
  return sink == 0 ? 0 : median(speedups);  // sink keeps the work from being optimized away
}

// fast_threaded on a scene with two threads against one (the same code with one thread), by the
// wall clock, alternating, median over rounds; and each thread's share drawn alone on the calling
// thread, by CPU time, which shows how evenly the bands split the work.
void threaded_probe(const BenchScene& scene, Canvas& canvas, int rounds, std::ostream& out) {
  std::vector<double> speedups, serial, shares[2];
  const auto wall_of = [&](int threads) {
    const auto start = Clock::now();
    for (int f = 0; f < 10; ++f) tri::ch08::draw_batch_on_threads(canvas, scene.triangles, threads);
    return std::chrono::duration<double>(Clock::now() - start).count();
  };
  const auto cpu_of = [&](int thread, int threads) {
    const double start = thread_cpu_seconds();
    for (int f = 0; f < 10; ++f)
      tri::ch08::draw_bands_of_thread(canvas, scene.triangles, thread, threads);
    return thread_cpu_seconds() - start;
  };
  wall_of(2);
  for (int r = 0; r < rounds; ++r) {
    speedups.push_back(wall_of(1) / wall_of(2));
    serial.push_back(cpu_of(0, 1));
    shares[0].push_back(cpu_of(0, 2));
    shares[1].push_back(cpu_of(1, 2));
  }
  const double whole = median(serial), first = median(shares[0]), second = median(shares[1]);
  out << "fast_threaded on the " << scene.name << " scene: two threads " << std::fixed
      << std::setprecision(2) << median(speedups)
      << "x the speed of one (wall clock); each thread's share drawn alone costs "
      << 100 * first / whole << "% and " << 100 * second / whole
      << "% of the serial draw (CPU time), an ideal speed-up of " << whole / std::max(first, second)
      << "\n";
}

int run(const tri::CliArguments& args, std::ostream& out) {
  const int repeats = static_cast<int>(args.integer("repeats", 1, 1000).value_or(7));
  const std::string scene_filter = args.value_or("scene", "");
  const auto frames = args.integer("frames", 1, 1000000);
  std::vector<TriangleAlgorithm> algorithms;
  for (const auto& a : tri::registered_algorithms()) {
    if (a.name == "barycentric_double" || a.name == "fixed_point_8") algorithms.push_back(a);
  }
  for (const auto& a : tri::ch08::triangle_algorithms()) {
    if (tri::find_algorithm(algorithms, a.name) == nullptr) algorithms.push_back(a);
  }
  // Names and scenes are checked before anything is measured: a typo is an error, not a table
  // without rows.
  std::vector<std::string> names;
  for (const auto& a : algorithms) names.emplace_back(a.name);
  if (const auto list = args.value("algos")) names = tri::parse_name_list("algos", *list, names);
  const std::vector<BenchScene> scenes = bench_scenes();
  if (std::none_of(scenes.begin(), scenes.end(), [&](const BenchScene& scene) {
        return scene.name.find(scene_filter) != std::string::npos;
      })) {
    std::string choices;
    for (const auto& scene : scenes) choices += (choices.empty() ? "" : "; ") + scene.name;
    throw tri::UsageError("--scene '" + tri::printable_excerpt(scene_filter) +
                          "' matches no scene (the scenes: " + choices + ")");
  }
  Canvas canvas(canvas_side, canvas_side);
  const double pixels_per_canvas = canvas_side * canvas_side;
  const std::array<std::uint32_t, 8> words{};
  bool header_written = false;  // written with the first rows, so a refused run prints no table
  for (const BenchScene& scene : scenes) {
    if (args.has("probes") || scene.name.find(scene_filter) == std::string::npos) continue;
    // The two ceilings, timed in the same rounds: std::fill over the canvas's Color pixels (what
    // Canvas::clear does, and what the targets name) and fill_pixels over the same memory.
    std::vector<Measurable> measurables;
    measurables.emplace_back("std::fill", [&] { canvas.clear(tri::Color{1, 2, 3, 255}); });
    measurables.emplace_back("fill_pixels", [&] {
      for (int y = 0; y < canvas_side; ++y)
        tri::ch08::fill_pixels(canvas.row(y).data(), canvas_side, words);
    });
    std::vector<const TriangleAlgorithm*> timed;
    for (const TriangleAlgorithm& algorithm : algorithms) {
      if (std::find(names.begin(), names.end(), algorithm.name) == names.end()) continue;
      timed.push_back(&algorithm);
      measurables.emplace_back(
          std::string(algorithm.name),
          [&, a = &algorithm] { timed_draw(*a, canvas, scene.triangles); }, algorithm.threaded);
    }
    // One call each tells how long the rounds will take: an absurd estimate is refused.
    double estimate = 0;
    for (Measurable& m : measurables) {
      const double once = seconds_of_one_call(m.run);
      m.frames = frames ? static_cast<int>(*frames) : frames_for(once);
      estimate += once * m.frames * (repeats + 1);
    }
    tri::refuse_absurd_run(estimate, "the " + scene.name + " scene", args.has("force"));
    tri::Progress progress("08_fast_exact_bench: " + scene.name,
                           static_cast<std::uint64_t>(repeats), std::cerr);
    measure_in_rounds(measurables, repeats, progress);
    if (!header_written) {
      out << "| scene | algorithm | Mtriangles/s | Mpixels/s | % of std::fill "
             "| x barycentric_double | Mtriangles/s, wall clock |\n"
             "|---|---|---:|---:|---:|---:|---:|\n";
      header_written = true;
    }
    const double std_fill_rate = pixels_per_canvas / median(measurables[0].cpu) / 1e6;
    const double wide_fill_rate = pixels_per_canvas / median(measurables[1].cpu) / 1e6;
    out << "| " << scene.name << " | (std::fill; fill_pixels) | | " << std::fixed
        << std::setprecision(0) << std_fill_rate << "; " << wide_fill_rate << " | 100 | | |\n";
    double baseline = 0;
    for (std::size_t i = 0; i < timed.size(); ++i) {
      const TriangleAlgorithm& algorithm = *timed[i];
      const Measurable& m = measurables[i + 2];
      // Threads spend CPU time on several cores at once: only the wall clock shows their gain.
      const double seconds = m.threaded ? median(m.wall) : median(m.cpu);
      if (algorithm.name == "barycentric_double") baseline = seconds;
      const double pixels = static_cast<double>(covered_pixels(algorithm, scene.triangles));
      const double pixel_rate = pixels / seconds / 1e6;
      out << "| " << scene.name << " | " << algorithm.name << " | " << std::defaultfloat
          << std::setprecision(3) << static_cast<double>(scene.triangles.size()) / seconds / 1e6
          << " | " << std::fixed << std::setprecision(0) << pixel_rate << " | "
          << 100 * pixel_rate / std_fill_rate << " | ";
      if (baseline > 0) out << std::setprecision(1) << baseline / seconds;
      out << " | " << std::defaultfloat << std::setprecision(3)
          << static_cast<double>(scene.triangles.size()) / median(m.wall) / 1e6 << " |\n";
    }
    out.flush();
  }
  if (scene_filter.empty() || args.has("probes")) {
    out << "\nTwo threads filling their own bands of the canvas with fill_pixels: " << std::fixed
        << std::setprecision(2) << two_thread_fill_speedup(canvas, repeats)
        << "x the speed of one thread (wall clock)\n";
    out << "Two threads sharing integer arithmetic: " << two_thread_arithmetic_speedup(repeats)
        << "x the speed of one thread (wall clock)\n";
    threaded_probe(scenes.front(), canvas, repeats, out);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const tri::CommandLine command_line(
      "08_fast_exact_bench",
      "Times chapter 08's variants (and fixed_point_8, barycentric_double) on large, tiny, mesh,\n"
      "mixed and sliver scenes of a 512x512 canvas, beside the std::fill rate of that canvas.\n"
      "Prints a Markdown table of medians. Build in Release; run on an otherwise idle machine.",
      {{"repeats", "N", "timed runs per measurement, the median is printed (default 7)"},
       {"algos", "A,B", "only these algorithms (comma-separated names)"},
       {"scene", "TEXT", "only the scenes whose name contains TEXT (e.g. tiny, mesh)"},
       {"frames", "N", "draw each scene N times per timed run (default: about 30 ms worth)"},
       {"probes", "", "only the two-thread probes: filling the canvas, and integer arithmetic"},
       {"force", "", "measure even when the estimated time exceeds 10 minutes"}});
  return tri::run_command_line(command_line, argc, argv, std::cout, std::cerr,
                               [&](const tri::CliArguments& args) { return run(args, std::cout); });
}
