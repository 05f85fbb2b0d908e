#include <cmath>
#include <set>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "chapters/10_speed_vs_error/suites.hpp"
#include "measure/render_scene.hpp"

using tri::SuiteScene;
using tri::ch10::BenchSettings;
using tri::ch10::SuiteSize;

namespace {

const std::vector<std::string> kinds{"tiny", "medium", "large", "slivers", "mesh", "fan", "mixed"};

}  // namespace

TEST_CASE("Every suite has the seven scene kinds on the integer grid, then on the 1/256 grid",
          "[10_speed_vs_error][step1][suites]") {
  for (const SuiteSize size : {SuiteSize::tiny, SuiteSize::quick, SuiteSize::full}) {
    const std::vector<SuiteScene> scenes = tri::ch10::scene_suite(size);
    REQUIRE(scenes.size() == 2 * kinds.size());
    for (std::size_t i = 0; i < scenes.size(); ++i) {
      CHECK(scenes[i].name == kinds[i % kinds.size()]);
      CHECK(scenes[i].grid == (i < kinds.size() ? "integer" : "1/256"));
      CHECK(scenes[i].recipe.grid_bits == (i < kinds.size() ? 0 : 8));
      CHECK(scenes[i].mesh == (scenes[i].name == "mesh" || scenes[i].name == "fan"));
      CHECK(scenes[i].recipe.width == scenes.front().recipe.width);
    }
  }
}

TEST_CASE(
    "The quick suite draws on 256x256 and the full one on 512x512 with a 100,000-triangle mesh",
    "[10_speed_vs_error][step1][suites]") {
  CHECK(tri::ch10::scene_suite(SuiteSize::quick).front().recipe.width == 256);
  const std::vector<SuiteScene> full = tri::ch10::scene_suite(SuiteSize::full);
  CHECK(full.front().recipe.width == 512);
  CHECK(full.front().recipe.height == 512);
  CHECK(tri::count_triangles(tri::generate_scene(full[4].recipe)) == 100352);
}

TEST_CASE("No two scenes of a suite share a seed", "[10_speed_vs_error][step1][suites]") {
  const std::vector<SuiteScene> scenes = tri::ch10::scene_suite(SuiteSize::quick);
  std::set<std::uint64_t> seeds;
  for (const SuiteScene& s : scenes) seeds.insert(s.recipe.seed);
  CHECK(seeds.size() == scenes.size());
}

TEST_CASE("Integer-grid scenes have integer vertices and 1/256-grid scenes multiples of 1/256",
          "[10_speed_vs_error][step1][suites]") {
  for (const SuiteScene& suite : tri::ch10::scene_suite(SuiteSize::tiny)) {
    const double scale = suite.recipe.grid_bits == 0 ? 1.0 : 256.0;
    bool any_fraction = false;
    for (const tri::SceneTriangle& t : tri::scene_triangles(tri::generate_scene(suite.recipe))) {
      for (const glm::dvec2& v : t.vertices) {
        CHECK(v.x * scale == std::floor(v.x * scale));
        CHECK(v.y * scale == std::floor(v.y * scale));
        any_fraction = any_fraction || v.x != std::floor(v.x) || v.y != std::floor(v.y);
      }
    }
    CHECK(any_fraction == (suite.recipe.grid_bits != 0));
  }
}

TEST_CASE("Grid labels name the integer and the 1/256 grid", "[10_speed_vs_error][step1][suites]") {
  CHECK(tri::ch10::grid_label(0) == "integer");
  CHECK(tri::ch10::grid_label(8) == "1/256");
  CHECK(tri::ch10::grid_label(4) == "1/2^4");
}

TEST_CASE("The tiny setting runs once per sample and measures error on whole scenes",
          "[10_speed_vs_error][step1][suites]") {
  const BenchSettings tiny = tri::ch10::bench_settings(SuiteSize::tiny);
  CHECK(tiny.timing.samples == 1);
  CHECK(tiny.timing.max_repetitions == 1);
  CHECK(tiny.error_triangle_limit == 0);
  const BenchSettings full = tri::ch10::bench_settings(SuiteSize::full);
  CHECK(full.error_triangle_limit == 0);
  CHECK(full.timing.min_sample_seconds >= 0.01);
}
