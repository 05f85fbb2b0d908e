// The sweeps of how cost grows: their scenes, the child that times a drawer and reads its peak
// memory, the budget that stops a slow drawer, and the CSV, table and plot. No speed is checked.
#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "chapters/10_speed_vs_error/scaling.hpp"
#include "chapters/10_speed_vs_error/scaling_report.hpp"
#include "measure/peers/external_peers.hpp"
#include "measure/registry.hpp"
#include "tests/support/text.hpp"

using tri::testing::occurrences;
using namespace tri::ch10;
using tri::PreparedScene;
using tri::SuiteScene;

namespace {

constexpr std::uint64_t mib = 1 << 20;

// AddressSanitizer keeps a shadow byte for every 8 bytes the program touches: memory the draw
// really adds, in the sanitize build only.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool address_sanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool address_sanitizer = true;
#else
constexpr bool address_sanitizer = false;
#endif
#else
constexpr bool address_sanitizer = false;
#endif

constexpr std::uint64_t address_sanitizer_shadow(std::uint64_t bytes) {
  return address_sanitizer ? bytes / 8 : 0;
}

// A drawer that takes no time of its own: it says a frame took `seconds(triangles)`.
ScalingDrawer pretend_drawer(std::string name, double seconds_per_triangle) {
  return {std::move(name), "test", false,
          [seconds_per_triangle](const PreparedScene& prepared, const tri::TimingPlan&) {
            tri::Timing timing;
            const double s = seconds_per_triangle * static_cast<double>(prepared.triangles.size());
            timing.seconds = {s, s, s};
            timing.repetitions = timing.samples = 1;
            return timing;
          }};
}

ScalingPoint point(std::string sweep, std::string drawer, std::string scene, int side,
                   std::size_t triangles, double seconds) {
  ScalingPoint p;
  p.sweep = std::move(sweep);
  p.drawer = std::move(drawer);
  p.chapter = "test";
  p.scene = std::move(scene);
  p.side = side;
  p.triangles = triangles;
  p.measured = seconds > 0;
  p.timing.seconds = {seconds, seconds, seconds};
  return p;
}

}  // namespace

TEST_CASE("The triangles sweep draws the suite's own scene kinds, only with more triangles",
          "[10_speed_vs_error][scaling]") {
  const SuiteScene tiny = triangles_sweep_scene("tiny", 100000, 256);
  CHECK(tiny.name == "tiny");
  CHECK(tiny.grid == "1/256");
  CHECK(tiny.recipe.triangles == 100000);
  CHECK(tiny.recipe.width == 256);
  CHECK(tiny.recipe.min_extent == 0.5);
  CHECK(tiny.recipe.max_extent == 2);
  // On 512x512 the mixed triangles are the full suite's: up to 128 pixels.
  const SuiteScene mixed = triangles_sweep_scene("mixed", 1000, 512);
  CHECK(mixed.recipe.max_extent == 128);
  CHECK(mixed.recipe.width == 512);
}

TEST_CASE("The canvas sweep scales the large triangles with the canvas",
          "[10_speed_vs_error][scaling]") {
  const SuiteScene quick = canvas_sweep_scene(256, 16);
  const SuiteScene big = canvas_sweep_scene(4096, 16);
  CHECK(big.recipe.width == 4096);
  CHECK(big.recipe.height == 4096);
  CHECK(big.recipe.triangles == 16);
  CHECK(big.recipe.min_extent == 16 * quick.recipe.min_extent);
  CHECK(big.recipe.max_extent == 16 * quick.recipe.max_extent);
}

TEST_CASE("The full sweeps reach 10^7 triangles and a 16384 x 16384 canvas, the quick ones less",
          "[10_speed_vs_error][scaling]") {
  const ScalingSettings full = scaling_settings(SuiteSize::full);
  CHECK(full.triangle_counts.front() == 1000);
  CHECK(full.triangle_counts.back() == 10000000);
  CHECK(full.canvas_sides.front() == 256);
  CHECK(full.canvas_sides.back() == tri::max_canvas_side);
  const ScalingSettings quick = scaling_settings(SuiteSize::quick);
  CHECK(quick.triangle_counts.back() == 100000);
  CHECK(quick.canvas_sides.back() == 2048);
}

TEST_CASE("A drawer is timed in a child process, which counts only the memory the draw adds",
          "[10_speed_vs_error][scaling]") {
  const PreparedScene prepared = prepare_scene(triangles_sweep_scene("tiny", 100, 32), 1);
  ScalingDrawer heavy = pretend_drawer("heavy", 0.001);
  const auto pretend = heavy.time;
  heavy.time = [pretend](const PreparedScene& p, const tri::TimingPlan& plan) {
    std::vector<char> touched(64 * mib, 1);  // 64 MiB written, so resident
    REQUIRE(touched[12345] == 1);
    return pretend(p, plan);
  };
  const ScalingPoint measured = measure_scaling_point(heavy, prepared, "triangles", {});
  REQUIRE(measured.measured);
  CHECK(measured.timing.seconds.median == Approx(0.1));
  CHECK(measured.triangles == 100);
  CHECK(measured.scene_bytes == 100 * sizeof(tri::SceneTriangle));
  CHECK(measured.peak_bytes >= 64 * mib);
  CHECK(measured.peak_bytes < 72 * mib + address_sanitizer_shadow(64 * mib));
  // This process's own memory (100 MiB it holds, and a peak of 200 MiB more it reached and gave
  // back) is not the child's draw.
  const std::vector<char> parent_memory(100 * mib, 1);
  REQUIRE(parent_memory[777] == 1);
  {
    const std::vector<char> given_back(200 * mib, 1);
    REQUIRE(given_back[888] == 1);
  }
  const ScalingPoint light =
      measure_scaling_point(pretend_drawer("light", 0.001), prepared, "triangles", {});
  CHECK(light.peak_bytes < 8 * mib);
}

TEST_CASE("A drawer that refuses a scene is reported as not measured, with its reason",
          "[10_speed_vs_error][scaling]") {
  const PreparedScene prepared = prepare_scene(canvas_sweep_scene(64, 2), 1);
  const ScalingDrawer refusing{"refusing", "test", false,
                               [](const PreparedScene&, const tri::TimingPlan&) -> tri::Timing {
                                 throw std::runtime_error("coordinates beyond its range");
                               }};
  const ScalingPoint p = measure_scaling_point(refusing, prepared, "canvas", {});
  CHECK_FALSE(p.measured);
  CHECK(p.not_measured_because == "coordinates beyond its range");
  CHECK(p.side == 64);
}

TEST_CASE("A drawer is not timed where its frame would take longer than the budget",
          "[10_speed_vs_error][scaling]") {
  ScalingSettings settings = scaling_settings(SuiteSize::tiny);
  settings.triangle_counts = {10, 20, 30};
  settings.canvas_sides = {16};
  settings.frame_budget_seconds = 2.5;
  // 0.1 s per triangle: 1 s for 10, then 2 s predicted for 20 (within), then 3 s predicted for
  // 30 (over), so 30 is skipped.
  const std::vector<ScalingDrawer> drawers{pretend_drawer("slow", 0.1),
                                           pretend_drawer("fast", 0.001)};
  std::ostringstream progress;
  const std::vector<ScalingPoint> points = run_scaling(drawers, settings, progress);
  REQUIRE(points.size() == 2 * 3 * 2 + 2);  // two kinds x three counts x two drawers, one canvas
  const auto at = [&](const std::string& drawer, const std::string& scene, std::size_t n) {
    const auto found = std::find_if(points.begin(), points.end(), [&](const ScalingPoint& p) {
      return p.sweep == "triangles" && p.drawer == drawer && p.scene == scene && p.triangles == n;
    });
    REQUIRE(found != points.end());
    return *found;
  };
  for (const std::string scene : {"tiny", "mixed"}) {
    CHECK(at("slow", scene, 10).measured);
    CHECK(at("slow", scene, 20).measured);
    CHECK_FALSE(at("slow", scene, 30).measured);
    CHECK_THAT(at("slow", scene, 30).not_measured_because,
               Catch::StartsWith("predicted 3.00 s per frame (2.00 s at 20 triangles on 32², in "
                                 "proportion), over the budget of 2.50 s"));
    CHECK(at("fast", scene, 30).measured);
  }
  CHECK(occurrences(progress.str(), "[scaling]") == points.size());
}

TEST_CASE("The sweeps follow fast_hybrid, the write ceiling and the peers that can be timed alone",
          "[10_speed_vs_error][scaling]") {
  const auto algorithms = tri::registered_algorithms();
  const auto peers = tri::external_peers();
  const std::vector<ScalingDrawer> drawers = scaling_drawers(algorithms, peers);
  REQUIRE(drawers.size() == 2 + peers.size());
  CHECK(drawers[0].name == "fast_hybrid");
  CHECK(drawers[1].name == "write_ceiling");
  CHECK(drawers[1].canvas_sweep_only);
  for (std::size_t i = 0; i < peers.size(); ++i) CHECK(drawers[2 + i].name == peers[i].name);
  // Without chapter 08's fastest among the algorithms, only the peers.
  const std::vector<tri::TriangleAlgorithm> others(algorithms.begin(), algorithms.begin() + 2);
  CHECK(scaling_drawers(others, peers).size() == peers.size());
}

TEST_CASE("Every drawer of this build draws both sweeps' smallest scenes",
          "[10_speed_vs_error][scaling]") {
  const auto drawers = scaling_drawers(tri::registered_algorithms(), tri::external_peers());
  std::ostringstream progress;
  const auto points = run_scaling(drawers, scaling_settings(SuiteSize::tiny), progress);
  for (const ScalingPoint& p : points) {
    INFO(p.drawer << " " << p.sweep << " " << p.scene << " " << p.triangles << ": "
                  << p.not_measured_because);
    CHECK(p.measured);
    CHECK(p.timing.seconds.median > 0);
  }
}

TEST_CASE("The growth exponent is the slope between the first and last measured points, log-log",
          "[10_speed_vs_error][scaling]") {
  const std::vector<ScalingPoint> points{
      point("triangles", "a", "tiny", 256, 1000, 0.001),
      point("triangles", "a", "tiny", 256, 10000, 0.01),
      point("triangles", "a", "tiny", 256, 100000, 0.1),
      point("triangles", "b", "tiny", 256, 1000, 0.001),
      point("triangles", "b", "tiny", 256, 10000, 0.1),
      point("triangles", "b", "tiny", 256, 100000, 0),  // not measured: b's last point is 10^4
      point("canvas", "a", "large", 256, 16, 0.001),
      point("canvas", "a", "large", 512, 16, 0.004)};
  CHECK(growth_exponent(points, "triangles", "tiny", "a") == Approx(1.0));
  CHECK(growth_exponent(points, "triangles", "tiny", "b") == Approx(2.0));
  CHECK(growth_exponent(points, "canvas", "large", "a") == Approx(1.0));  // 4x pixels, 4x time
  CHECK(growth_exponent(points, "triangles", "mixed", "a") == 0);
}

TEST_CASE("The sweeps' CSV, table and plots show every point, and why one was not measured",
          "[10_speed_vs_error][scaling]") {
  std::vector<ScalingPoint> points{point("triangles", "a", "tiny", 256, 1000, 0.001),
                                   point("triangles", "b", "tiny", 256, 1000, 0.002),
                                   point("triangles", "a", "tiny", 256, 10000, 0.01),
                                   point("triangles", "b", "tiny", 256, 10000, 0),
                                   point("canvas", "a", "large", 256, 16, 0.001),
                                   point("canvas", "a", "large", 512, 16, 0.004)};
  points[3].not_measured_because = "refused, with a comma";
  points[0].peak_bytes = 3 * mib / 2;
  points[0].scene_bytes = 56000;
  points[2].timing.seconds = {1.2391, 1.2391, 1.2391};
  const std::string csv = scaling_csv(points);
  CHECK(occurrences(csv, "\n") == points.size() + 1);
  CHECK_THAT(csv, Catch::StartsWith("sweep,drawer,chapter,scene,side,triangles,"));
  CHECK_THAT(csv, Catch::Contains(",\"refused, with a comma\"\n"));

  const std::string md = scaling_markdown(points);
  CHECK_THAT(md, Catch::Contains("## How cost grows"));
  CHECK_THAT(md, Catch::Contains("| tiny | 1000 | 54.7 KiB | 1 ms · +1.5 MiB | 2 ms · +0 bytes |"));
  CHECK_THAT(md, Catch::Contains("| 1239 ms · +0 bytes |"));
  CHECK_THAT(md, Catch::Contains("| tiny | 10000 |"));
  CHECK_THAT(md, Catch::Contains("| 512×512 | 16 |"));
  CHECK_THAT(md, Catch::Contains(" – |"));
  CHECK_THAT(md, Catch::Contains("not measured, refused, with a comma"));
  CHECK_THAT(md, Catch::Contains("`a` tiny k = 3.1"));  // 1 ms to 1239 ms for 10 times more
  CHECK_THAT(md, Catch::Contains("`a` k = 1."));        // 4 times the pixels, 4 times the time
  CHECK(scaling_markdown({}).empty());

  const std::string triangles = scaling_svg(points, "triangles", "a subtitle");
  CHECK(occurrences(triangles, "<circle") == 3);  // the measured points of that sweep
  CHECK_THAT(triangles, Catch::Contains(">a</text>"));
  CHECK_THAT(triangles, Catch::Contains(">b</text>"));
  CHECK_THAT(triangles, Catch::Contains("a subtitle"));
  const std::string canvas = scaling_svg(points, "canvas", "a subtitle");
  CHECK(occurrences(canvas, "<circle") == 2);
  CHECK_THAT(canvas, Catch::Contains("pixels of the canvas"));
}
