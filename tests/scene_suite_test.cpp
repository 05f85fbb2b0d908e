// The large seeded scenes of the exactness claim: every top-left algorithm draws exactly the
// oracle's pixels on 10,000-triangle scenes of every family, with vertices on the 1/256 grid.
#include <catch2/catch.hpp>

#include <string>

#include "measure/error_metrics.hpp"
#include "measure/registry.hpp"
#include "measure/scene_generators.hpp"
#include "tests/hard_cases/deviation_checks.hpp"
#include "tests/suite_recipes.hpp"

namespace {

using Kind = tri::SceneRecipe::Kind;

struct Family {
  std::string name;
  tri::SceneRecipe recipe;
};

std::vector<Family> families() {
  const auto recipe = tri::test::ten_thousand;
  return {
      {"random", recipe(Kind::random, 1, 40, 1)},
      {"tiny", recipe(Kind::random, 0.5, 2.5, 2)},
      {"large", recipe(Kind::random, 60, 120, 3)},
      {"slivers", recipe(Kind::slivers, 10, 200, 4)},
      {"fan", recipe(Kind::fan, 0, 0, 5)},
      {"jittered grid mesh", recipe(Kind::jittered_grid, 0, 0, 6)},
  };
}

}  // namespace

TEST_CASE("Every top-left algorithm matches the oracle on 10,000-triangle scenes of every family",
          "[scene_suite]") {
  for (const auto& family : families()) {
    const tri::Scene scene = tri::generate_scene(family.recipe);
    REQUIRE(scene.primitives.size() >= 10000);
    for (const auto& algorithm : tri::registered_algorithms()) {
      // The oracle against itself proves nothing and is the slowest to run.
      if (algorithm.rule != tri::CoverageRule::top_left || algorithm.name == "exact_oracle")
        continue;
      INFO(algorithm.name << " on " << family.name);
      const tri::ErrorReport e = tri::measure_error(algorithm, scene);
      CHECK(e.covered > 0);
      tri::testing::check_no_deviation(e);
      CHECK(e.outside_writes == 0);
    }
  }
}

TEST_CASE("Meshes drawn by a top-left algorithm cover each interior pixel exactly once",
          "[scene_suite]") {
  for (const Kind kind : {Kind::fan, Kind::jittered_grid}) {
    tri::SceneRecipe recipe;
    recipe.kind = kind;
    recipe.triangles = 10000;
    recipe.seed = 11;
    const tri::Scene scene = tri::generate_scene(recipe);
    for (const auto& algorithm : tri::registered_algorithms()) {
      if (algorithm.rule != tri::CoverageRule::top_left) continue;
      INFO(algorithm.name);
      tri::Canvas canvas(scene.width, scene.height);
      canvas.enable_write_counts();
      std::vector<tri::SceneTriangle> triangles;
      for (const auto& p : scene.primitives) triangles.push_back(std::get<tri::SceneTriangle>(p));
      tri::draw_triangles(algorithm, canvas, triangles);
      std::uint64_t once = 0, more = 0;
      for (const auto count : canvas.write_counts()) {
        once += count == 1;
        more += count > 1;
      }
      CHECK(more == 0);
      if (kind == Kind::jittered_grid) {
        // The grid reaches past every side of the canvas, so every pixel is interior.
        CHECK(once == static_cast<std::uint64_t>(scene.width) * scene.height);
      } else {
        CHECK(once > 0);
      }
    }
  }
}

TEST_CASE("The scene generators are deterministic and give the families their shapes",
          "[scene_suite]") {
  for (const auto& family : families()) {
    const tri::Scene a = tri::generate_scene(family.recipe);
    const tri::Scene b = tri::generate_scene(family.recipe);
    REQUIRE(a.primitives.size() == b.primitives.size());
    for (std::size_t i = 0; i < a.primitives.size(); ++i) {
      const auto& ta = std::get<tri::SceneTriangle>(a.primitives[i]);
      const auto& tb = std::get<tri::SceneTriangle>(b.primitives[i]);
      for (int k = 0; k < 3; ++k) {
        REQUIRE(ta.vertices[k] == tb.vertices[k]);
        // On the 1/256 grid.
        REQUIRE(ta.vertices[k].x * 256 == std::floor(ta.vertices[k].x * 256));
        REQUIRE(ta.vertices[k].y * 256 == std::floor(ta.vertices[k].y * 256));
      }
    }
  }
}
