// The hard cases of docs/DESIGN.md section 7 for the coverage algorithms (rule `area`): the cell
// method is within one 16-bit unit of the exact area wherever the oracle is exact, and every
// coverage algorithm refuses what the triangle algorithms refuse.
#include <catch2/catch.hpp>

#include "measure/area_error.hpp"
#include "measure/registry.hpp"
#include "measure/hard_cases.hpp"

TEST_CASE("area_cells is within one 16-bit unit of the exact area on every hard case on the grid",
          "[hard_cases][area]") {
  const auto algorithms = tri::registered_area_algorithms();
  const auto* area_cells = tri::find_named(algorithms, "area_cells");
  REQUIRE(area_cells != nullptr);
  int measured = 0;
  for (const auto& hard_case : tri::hard_cases::all_cases()) {
    if (hard_case.expect_rejection) continue;
    INFO(hard_case.name);
    const tri::AreaErrorReport e = tri::measure_area_error(*area_cells, hard_case.scene);
    if (e.triangles == 0) continue;  // every triangle off the oracle's grid or range
    ++measured;
    CHECK(e.max_units <= 1);
    CHECK(e.composed_off_pixels == 0);
  }
  CHECK(measured >= 20);
}

TEST_CASE("Every coverage algorithm refuses the non-finite hard cases and draws nothing",
          "[hard_cases][area]") {
  for (const auto& algorithm : tri::registered_area_algorithms()) {
    for (const auto& hard_case : tri::hard_cases::all_cases()) {
      if (!hard_case.expect_rejection) continue;
      INFO(algorithm.name << " on " << hard_case.name);
      std::vector<tri::SceneTriangle> triangles;
      for (const auto& p : hard_case.scene.primitives) {
        if (const auto* t = std::get_if<tri::SceneTriangle>(&p)) triangles.push_back(*t);
      }
      tri::ch09::CoverageCanvas canvas(hard_case.scene.width, hard_case.scene.height);
      CHECK(tri::ch09::draw_coverage(algorithm, canvas, triangles) == triangles.size());
      int touched = 0;
      for (int y = 0; y < canvas.height(); ++y) {
        for (int x = 0; x < canvas.width(); ++x) touched += canvas.at(x, y) != 0;
      }
      CHECK(touched == 0);
    }
  }
}
