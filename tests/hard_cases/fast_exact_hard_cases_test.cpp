// The repository's hard cases (tests/hard_cases) run on this chapter's variants here as well, so
// that `ctest -R 08_fast_exact` alone shows whether a change to the chapter broke one.
#include <catch2/catch.hpp>

#include <vector>

#include "chapters/08_fast_exact/algorithms.hpp"
#include "chapters/08_fast_exact/test_triangles.hpp"
#include "measure/hard_cases.hpp"
#include "measure/render_scene.hpp"
#include "tests/hard_cases/deviation_checks.hpp"

TEST_CASE("Every variant of the chapter is safe and exact on every hard case", "[hard_cases]") {
  for (const auto& algorithm : tri::ch08::triangle_algorithms()) {
    for (const auto& c : tri::hard_cases::all_cases()) {
      INFO(algorithm.name << " on " << c.name);
      const auto outcome = tri::hard_cases::run_case(algorithm, c);
      CHECK(outcome.safe);
      CHECK(outcome.error.outside_writes == 0);
      tri::testing::check_no_deviation(outcome.error);
    }
  }
}

TEST_CASE("Every narrow draw of the chapter gives the oracle's pixels on every hard case",
          "[hard_cases]") {
  int narrow_draws = 0, drawn = 0;
  for (const auto& algorithm : tri::ch08::triangle_algorithms()) {
    if (algorithm.draw_narrow == nullptr) continue;
    ++narrow_draws;
    for (const auto& c : tri::hard_cases::all_cases()) {
      INFO(algorithm.name << " on " << c.name);
      std::vector<tri::SceneTriangle> valid;
      for (const tri::SceneTriangle& t : tri::scene_triangles(c.scene)) {
        if (tri::validate_triangle(t.vertices) == tri::DrawResult::drawn) valid.push_back(t);
      }
      CHECK(tri::ch08::testing::narrow_pixels_off_oracle(
                algorithm.draw_narrow, valid, c.scene.width, c.scene.height, drawn) == 0);
    }
  }
  CHECK(narrow_draws >= 2);  // the span walker alone and after the batched setup
  CHECK(drawn > 1000);
}
