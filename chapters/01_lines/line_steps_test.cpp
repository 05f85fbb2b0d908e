// The step-by-step comparison behind the chapter's figures, and the star's ties they show.
#include <catch2/catch.hpp>

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "chapters/01_lines/line_steps.hpp"

using tri::ch01::line_algorithms;
using tri::ch01::star_spokes;
using tri::ch01::steps_against_exact;

namespace {

void draw_nothing(tri::Canvas&, glm::ivec2, glm::ivec2, tri::Color) {}

}  // namespace

TEST_CASE("steps_against_exact pairs DDA's two directions on (0,0)-(12,1) with the exact pixels",
          "[01_lines][line_steps][steps]") {
  const auto right = steps_against_exact(tri::ch01::draw_line_dda, {0, 0}, {12, 1});
  const auto left = steps_against_exact(tri::ch01::draw_line_dda, {12, 1}, {0, 0});
  REQUIRE(right.size() == 13);
  REQUIRE(left.size() == 13);
  for (std::size_t k = 0; k < right.size(); ++k) {
    CHECK(right[k].exact.pixel == glm::ivec2(static_cast<int>(k), k >= 6 ? 1 : 0));
    CHECK(right[k].exact.tie == (k == 6));
    CHECK(left[k].exact.pixel == right[k].exact.pixel);
    if (k != 6) {
      CHECK(right[k].drawn == right[k].exact.pixel);
      CHECK(left[k].drawn == left[k].exact.pixel);
    }
  }
  CHECK(right[6].drawn == glm::ivec2(6, 1));  // the tie goes up from the left end
  CHECK(left[6].drawn == glm::ivec2(6, 0));   // and down from the right end
}

TEST_CASE("steps_against_exact steps along y for a steep line", "[01_lines][line_steps][steps]") {
  const auto steps = steps_against_exact(tri::ch01::draw_line_bresenham, {22, 1}, {20, 13});
  REQUIRE(steps.size() == 13);
  CHECK(steps.front().drawn == glm::ivec2(22, 1));
  CHECK(steps.back().drawn == glm::ivec2(20, 13));
  CHECK(steps[3].exact.tie);  // x = 22 - 3/6 = 21.5 at y = 4
  CHECK(steps[3].exact.pixel == glm::ivec2(22, 4));
  CHECK(steps[3].drawn == glm::ivec2(22, 4));  // toward the bottom end (22, 1)
}

TEST_CASE("steps_against_exact refuses negative coordinates and a step left empty",
          "[01_lines][line_steps][steps]") {
  CHECK_THROWS_AS(steps_against_exact(tri::ch01::draw_line_dda, {-1, 0}, {3, 3}),
                  std::invalid_argument);
  CHECK_THROWS_AS(steps_against_exact(draw_nothing, {0, 0}, {3, 3}), std::logic_error);
}

TEST_CASE("The star's 24 spokes have 8 tie steps, and the algorithms split 2 against 2 at 6",
          "[01_lines][line_steps][steps]") {
  const auto spokes = star_spokes({32, 32}, 30, 24);
  REQUIRE(spokes.size() == 24);
  CHECK(spokes[0][1] == glm::ivec2(62, 32));
  CHECK(spokes[2][1] == glm::ivec2(58, 47));
  CHECK(spokes[6][1] == glm::ivec2(32, 62));
  std::vector<std::string> splits;  // per tie step, one letter per algorithm: U up, D down
  for (const auto& spoke : spokes) {
    std::vector<std::vector<tri::ch01::LineStep>> runs;
    for (const auto& algorithm : line_algorithms) {
      runs.push_back(steps_against_exact(algorithm.draw, spoke[0], spoke[1]));
    }
    for (std::size_t k = 0; k < runs[0].size(); ++k) {
      if (!runs[0][k].exact.tie) {
        for (const auto& run : runs) CHECK(run[k].drawn == run[k].exact.pixel);
        continue;
      }
      std::string split;
      for (const auto& run : runs) split += run[k].drawn == run[k].exact.pixel ? 'U' : 'D';
      splits.push_back(split);
    }
  }
  // Gambetta, DDA, Bresenham, midpoint, spoke by spoke counterclockwise from spoke 2 at 30°.
  CHECK(splits ==
        std::vector<std::string>{"UUDD", "UUDD", "UUUU", "DUUD", "DUDU", "DUDU", "DUUD", "UUUU"});
}
