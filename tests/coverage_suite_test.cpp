// The exact-area claim of chapter 09 on large seeded scenes: the cell method agrees with the
// exact oracle within one unit of the 16-bit output, triangle by triangle and for the scene.
#include <catch2/catch.hpp>

#include <string>

#include "measure/area_error.hpp"
#include "measure/registry.hpp"
#include "measure/scene_generators.hpp"
#include "tests/suite_recipes.hpp"

namespace {

using Kind = tri::SceneRecipe::Kind;

constexpr auto recipe = tri::test::ten_thousand;

const tri::ch09::AreaAlgorithm& area_cells() {
  static const auto algorithms = tri::registered_area_algorithms();
  return *tri::find_named(algorithms, "area_cells");
}

}  // namespace

TEST_CASE("area_cells is within one 16-bit unit of the exact area on 10,000-triangle scenes",
          "[coverage_suite]") {
  const std::pair<std::string, tri::SceneRecipe> families[] = {
      {"random", recipe(Kind::random, 1, 40, 21)},
      {"tiny", recipe(Kind::random, 0.5, 2.5, 22)},
      {"slivers", recipe(Kind::slivers, 10, 200, 23)},
      {"jittered grid mesh", recipe(Kind::jittered_grid, 0, 0, 24)},
  };
  for (const auto& [name, r] : families) {
    INFO(name);
    const tri::Scene scene = tri::generate_scene(r);
    const tri::AreaErrorReport e = tri::measure_area_error(area_cells(), scene);
    CHECK(e.triangles >= 10000);
    CHECK(e.rejected == 0);
    CHECK(e.pixels > e.triangles);
    CHECK(e.max_units <= 1);
    CHECK(e.max < 1.0 / 65535);
    CHECK(e.composed_off_pixels == 0);
  }
}

TEST_CASE("A mesh composited as alpha shows seams and a summed mesh does not", "[coverage_suite]") {
  const tri::Scene mesh = tri::generate_scene(recipe(Kind::jittered_grid, 0, 0, 25));
  const auto algorithms = tri::registered_area_algorithms();
  const auto* over = tri::find_named(algorithms, "area_cells_over");
  REQUIRE(over != nullptr);
  const tri::AreaErrorReport summed = tri::measure_area_error(area_cells(), mesh);
  const tri::AreaErrorReport composited = tri::measure_area_error(*over, mesh);
  // Triangle by triangle both are the exact area; only the composition differs.
  CHECK(composited.max_units <= 1);
  CHECK(summed.composed_off_pixels == 0);
  CHECK(composited.composed_off_pixels > composited.composed_pixels / 4);
  CHECK(composited.composed_max > 0.2);
}
