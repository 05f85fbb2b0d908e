// The four line algorithms of the chapter, checked against the exact nearest pixel per step.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "chapters/01_lines/line_algorithms.hpp"
#include "chapters/01_lines/line_reference.hpp"
#include "tests/support/pixels.hpp"

using namespace tri::ch01;
using namespace tri::testing;
using tri::Canvas;

namespace {

constexpr int canvas_size = 64;
constexpr int two_30 = 1 << 30;

struct Line {
  glm::ivec2 p0, p1;
};

// The segment seen along its major axis (x when |dx| >= |dy|, as the exact reference decides).
struct Axes {
  bool x_major;
  std::int64_t major(glm::ivec2 p) const { return x_major ? p.x : p.y; }
  std::int64_t minor(glm::ivec2 p) const { return x_major ? p.y : p.x; }
  glm::ivec2 minor_unit() const { return x_major ? glm::ivec2(0, 1) : glm::ivec2(1, 0); }
};

Axes axes_of(const Line& line) {
  const std::int64_t dx = std::abs(static_cast<std::int64_t>(line.p1.x) - line.p0.x);
  const std::int64_t dy = std::abs(static_cast<std::int64_t>(line.p1.y) - line.p0.y);
  return {dx >= dy};
}

Canvas draw(const LineAlgorithm& algorithm, glm::ivec2 from, glm::ivec2 to) {
  Canvas canvas(canvas_size, canvas_size);
  canvas.enable_write_counts();
  algorithm.draw(canvas, from, to, tri::colors::white);
  return canvas;
}

PixelSet drawn_pixels(const LineAlgorithm& algorithm, glm::ivec2 from, glm::ivec2 to) {
  return written_pixels(draw(algorithm, from, to));
}

Line random_line(Random& random, int low, int high) {
  return {{random.integer(low, high), random.integer(low, high)},
          {random.integer(low, high), random.integer(low, high)}};
}

// Minor coordinates drawn at each major coordinate (only on-canvas pixels are visible).
std::map<std::int64_t, std::vector<std::int64_t>> minors_by_major(const PixelSet& pixels,
                                                                  Axes axes) {
  std::map<std::int64_t, std::vector<std::int64_t>> result;
  for (const auto& [x, y] : pixels) {
    const glm::ivec2 p(x, y);
    result[axes.major(p)].push_back(axes.minor(p));
  }
  return result;
}

// At a tie the exact reference picks the upper pixel r (the line runs through r - 1/2); this
// returns the candidate on the side of `toward` instead, which is how Bresenham and midpoint
// break ties.
glm::ivec2 tie_broken_toward(const ExactLinePixel& exact, Axes axes, glm::ivec2 toward) {
  if (!exact.tie || axes.minor(toward) >= axes.minor(exact.pixel)) return exact.pixel;
  return exact.pixel - axes.minor_unit();
}

bool on_canvas(glm::ivec2 p) {
  return p.x >= 0 && p.x < canvas_size && p.y >= 0 && p.y < canvas_size;
}

// The on-canvas pixels of the exact line with each tie sent toward `toward`.
PixelSet expected_with_ties_toward(const Line& line, glm::ivec2 toward) {
  const Axes axes = axes_of(line);
  PixelSet expected;
  for (const ExactLinePixel& exact : exact_line_pixels(line.p0, line.p1)) {
    const glm::ivec2 p = tie_broken_toward(exact, axes, toward);
    if (on_canvas(p)) expected.emplace(p.x, p.y);
  }
  return expected;
}

glm::ivec2 smaller_major_endpoint(const Line& line) {
  const Axes axes = axes_of(line);
  return axes.major(line.p0) <= axes.major(line.p1) ? line.p0 : line.p1;
}

// Draws 2000 seeded lines with `algorithm`, each from both ends, and checks every drawing against
// the exact line with its ties sent toward tie_toward(line, start). Half the lines stay on the
// canvas, half leave it (then the walk starts mid-line).
template <typename TieToward>
void check_ties_on_seeded_lines(const LineAlgorithm& algorithm, std::uint64_t seed,
                                TieToward tie_toward) {
  Random random(seed);
  for (int trial = 0; trial < 2000; ++trial) {
    const Line line = trial % 2 == 0 ? random_line(random, 0, canvas_size - 1)
                                     : random_line(random, -60, canvas_size + 60);
    CAPTURE(line.p0.x, line.p0.y, line.p1.x, line.p1.y);
    CHECK(drawn_pixels(algorithm, line.p0, line.p1) ==
          expected_with_ties_toward(line, tie_toward(line, line.p0)));
    CHECK(drawn_pixels(algorithm, line.p1, line.p0) ==
          expected_with_ties_toward(line, tie_toward(line, line.p1)));
  }
}

// Checks what a drawing of `line` shows against the exact line: at every step the pixel is the
// exact one, or at a tie one of the two pixels the line passes between; nothing is drawn twice
// and nothing is drawn off the line's steps. Pixels off the canvas are invisible, so a step may
// show nothing when its pixel (or, at a tie, one of the candidates) lies outside.
void check_drawing_against_exact(const Canvas& canvas, const Line& line) {
  CAPTURE(line.p0.x, line.p0.y, line.p1.x, line.p1.y);
  CHECK(overdrawn_pixels(canvas).empty());
  const Axes axes = axes_of(line);
  auto drawn = minors_by_major(written_pixels(canvas), axes);
  for (const ExactLinePixel& exact : exact_line_pixels(line.p0, line.p1)) {
    const glm::ivec2 lower = exact.pixel - axes.minor_unit();
    const std::vector<std::int64_t> minors = drawn[axes.major(exact.pixel)];
    drawn.erase(axes.major(exact.pixel));
    CAPTURE(exact.pixel.x, exact.pixel.y, exact.tie);
    REQUIRE(minors.size() <= 1);
    if (!exact.tie) {
      CHECK(minors.size() == (on_canvas(exact.pixel) ? 1u : 0u));
      if (minors.size() == 1) CHECK(minors.front() == axes.minor(exact.pixel));
    } else if (minors.empty()) {
      CHECK(!(on_canvas(exact.pixel) && on_canvas(lower)));
    } else {
      CHECK((minors.front() == axes.minor(exact.pixel) || minors.front() == axes.minor(lower)));
    }
  }
  CHECK(drawn.empty());  // no pixel at a major coordinate outside the segment
}

std::string_view octant_of(const Line& line) {
  const auto dx = static_cast<std::int64_t>(line.p1.x) - line.p0.x;
  const auto dy = static_cast<std::int64_t>(line.p1.y) - line.p0.y;
  const bool steep = std::abs(dy) > std::abs(dx);
  if (dx >= 0 && dy >= 0) return steep ? "NNE" : "ENE";
  if (dx < 0 && dy >= 0) return steep ? "NNW" : "WNW";
  if (dx < 0) return steep ? "SSW" : "WSW";
  return steep ? "SSE" : "ESE";
}

// 2000 lines with both endpoints on the 64x64 canvas, the same on every machine.
std::vector<Line> seeded_canvas_lines() {
  Random random(2024);
  std::vector<Line> lines;
  for (int i = 0; i < 2000; ++i) lines.push_back(random_line(random, 0, canvas_size - 1));
  return lines;
}

}  // namespace

TEST_CASE("The seeded random lines cover all eight octants", "[01_lines][step3][lines]") {
  std::map<std::string_view, int> count;
  for (const Line& line : seeded_canvas_lines()) ++count[octant_of(line)];
  CHECK(count.size() == 8);
  for (const auto& [octant, n] : count) {
    CAPTURE(octant);
    CHECK(n >= 150);
  }
}

TEST_CASE("Every line algorithm draws a short line in each octant as its nearest pixels",
          "[01_lines][step3][lines]") {
  const LineAlgorithm algorithm = GENERATE(from_range(line_algorithms));
  CAPTURE(algorithm.name);
  // From (10,10), a third of a pixel per step: no ties, and truncating 2/3 to 0 would be wrong.
  const glm::ivec2 c(10, 10);
  const std::vector<std::pair<glm::ivec2, PixelSet>> cases = {
      {{13, 11}, {{10, 10}, {11, 10}, {12, 11}, {13, 11}}},
      {{11, 13}, {{10, 10}, {10, 11}, {11, 12}, {11, 13}}},
      {{9, 13}, {{10, 10}, {10, 11}, {9, 12}, {9, 13}}},
      {{7, 11}, {{10, 10}, {9, 10}, {8, 11}, {7, 11}}},
      {{7, 9}, {{10, 10}, {9, 10}, {8, 9}, {7, 9}}},
      {{9, 7}, {{10, 10}, {10, 9}, {9, 8}, {9, 7}}},
      {{11, 7}, {{10, 10}, {10, 9}, {11, 8}, {11, 7}}},
      {{13, 9}, {{10, 10}, {11, 10}, {12, 9}, {13, 9}}},
  };
  for (const auto& [tip, expected] : cases) {
    CAPTURE(tip.x, tip.y);
    CHECK(drawn_pixels(algorithm, c, tip) == expected);
    CHECK(drawn_pixels(algorithm, tip, c) == expected);
  }
}

TEST_CASE("Every line algorithm draws a zero-length line as exactly its one pixel",
          "[01_lines][traps][lines]") {
  const LineAlgorithm algorithm = GENERATE(from_range(line_algorithms));
  CAPTURE(algorithm.name);
  for (const glm::ivec2 p :
       {glm::ivec2(0, 0), glm::ivec2(63, 63), glm::ivec2(0, 63), glm::ivec2(17, 42)}) {
    CAPTURE(p.x, p.y);
    const Canvas canvas = draw(algorithm, p, p);
    CHECK(written_pixels(canvas) == PixelSet{{p.x, p.y}});
    CHECK(canvas.write_count(p.x, p.y) == 1);
    CHECK(canvas.outside_writes() == 0);
  }
}

TEST_CASE("Every line algorithm draws both endpoints and one pixel per step of the major axis",
          "[01_lines][traps][lines]") {
  const LineAlgorithm algorithm = GENERATE(from_range(line_algorithms));
  CAPTURE(algorithm.name);
  for (const Line& line : seeded_canvas_lines()) {
    CAPTURE(line.p0.x, line.p0.y, line.p1.x, line.p1.y);
    const Canvas canvas = draw(algorithm, line.p0, line.p1);
    const PixelSet pixels = written_pixels(canvas);
    const Axes axes = axes_of(line);
    const std::int64_t low = std::min(axes.major(line.p0), axes.major(line.p1));
    const std::int64_t n = std::abs(axes.major(line.p1) - axes.major(line.p0));
    CHECK(canvas.outside_writes() == 0);
    CHECK(pixels.size() == static_cast<std::size_t>(n + 1));
    CHECK(overdrawn_pixels(canvas).empty());
    CHECK(pixels.count({line.p0.x, line.p0.y}) == 1);
    CHECK(pixels.count({line.p1.x, line.p1.y}) == 1);
    const auto by_major = minors_by_major(pixels, axes);
    REQUIRE(by_major.size() == static_cast<std::size_t>(n + 1));  // each major coordinate once
    CHECK(by_major.begin()->first == low);
    CHECK(by_major.rbegin()->first == low + n);
    // 8-connected: consecutive steps move the minor coordinate by at most one.
    for (auto it = by_major.begin(); std::next(it) != by_major.end(); ++it) {
      CHECK(std::abs(std::next(it)->second.front() - it->second.front()) <= 1);
    }
  }
}

TEST_CASE("Every line algorithm draws the nearest pixel at every step that is not a tie",
          "[01_lines][step3][lines]") {
  const LineAlgorithm algorithm = GENERATE(from_range(line_algorithms));
  CAPTURE(algorithm.name);
  for (const Line& line : seeded_canvas_lines()) {
    check_drawing_against_exact(draw(algorithm, line.p0, line.p1), line);
  }
}

TEST_CASE("Every line algorithm shows, of a line leaving the canvas, the exact pixels on it",
          "[01_lines][step3][lines]") {
  const LineAlgorithm algorithm = GENERATE(from_range(line_algorithms));
  CAPTURE(algorithm.name);
  Random random(77);
  for (int trial = 0; trial < 1000; ++trial) {
    const Line line = random_line(random, -40, canvas_size + 40);
    check_drawing_against_exact(draw(algorithm, line.p0, line.p1), line);
  }
}

TEST_CASE("Every line algorithm draws (0,0)-(4,2), whose steps 1 and 3 are ties, as pinned",
          "[01_lines][step3][lines][ties]") {
  const PixelSet up{{0, 0}, {1, 1}, {2, 1}, {3, 2}, {4, 2}};    // ties rounded up
  const PixelSet down{{0, 0}, {1, 0}, {2, 1}, {3, 1}, {4, 2}};  // ties rounded down
  const std::map<std::string_view, std::pair<PixelSet, PixelSet>> expected = {
      {"gambetta", {up, up}},  // slope 0.5 is exact in binary: round half up both ways
      {"dda", {up, up}},
      {"bresenham", {down, down}},  // towards (0,0), the end with the smaller x
      {"midpoint", {down, up}},     // towards p0, whichever end that is
  };
  for (const LineAlgorithm& algorithm : line_algorithms) {
    CAPTURE(algorithm.name);
    CHECK(drawn_pixels(algorithm, {0, 0}, {4, 2}) == expected.at(algorithm.name).first);
    CHECK(drawn_pixels(algorithm, {4, 2}, {0, 0}) == expected.at(algorithm.name).second);
  }
}

TEST_CASE("DDA draws (0,0)-(12,1) differently in the two directions, at its tie x = 6",
          "[01_lines][step4][lines][ties]") {
  // Both sums land just below 0.5: 0 + 6 x 1/12 by one ulp, which floor(v + 0.5) still rounds
  // up, and 1 - 6 x 1/12 by three, which it rounds down. The float sum decides the tie.
  PixelSet forward, backward;
  for (int x = 0; x <= 12; ++x) {
    forward.emplace(x, x < 6 ? 0 : 1);
    backward.emplace(x, x <= 6 ? 0 : 1);
  }
  const LineAlgorithm& dda = line_algorithms[1];
  REQUIRE(dda.name == "dda");
  CHECK(exact_line_pixel_at({0, 0}, {12, 1}, 6).tie);
  CHECK(drawn_pixels(dda, {0, 0}, {12, 1}) == forward);
  CHECK(drawn_pixels(dda, {12, 1}, {0, 0}) == backward);
}

TEST_CASE(
    "line algorithms draw the same pixels in both directions when they promise to, and otherwise "
    "differ only at ties",
    "[01_lines][step4][lines][ties]") {
  const LineAlgorithm algorithm = GENERATE(from_range(line_algorithms));
  CAPTURE(algorithm.name);
  int lines_that_differ = 0;
  for (const Line& line : seeded_canvas_lines()) {
    CAPTURE(line.p0.x, line.p0.y, line.p1.x, line.p1.y);
    const PixelSet forward = drawn_pixels(algorithm, line.p0, line.p1);
    const PixelSet backward = drawn_pixels(algorithm, line.p1, line.p0);
    if (algorithm.same_pixels_both_directions) {
      CHECK(forward == backward);
      continue;
    }
    if (forward != backward) ++lines_that_differ;
    const Axes axes = axes_of(line);
    auto backward_by_major = minors_by_major(backward, axes);
    for (const auto& [major, minors] : minors_by_major(forward, axes)) {
      if (backward_by_major[major] == minors) continue;
      CAPTURE(major);
      CHECK(exact_line_pixel_at(line.p0, line.p1, major).tie);
    }
  }
  // How many of the 2000 seeded lines change with the direction (measured, then pinned).
  const std::map<std::string_view, int> expected_differing = {
      {"gambetta", 0}, {"dda", 433}, {"bresenham", 0}, {"midpoint", 685}};
  CHECK(lines_that_differ == expected_differing.at(algorithm.name));
}

TEST_CASE("Bresenham breaks ties toward the endpoint with the smaller major coordinate",
          "[01_lines][step5][lines][ties][bresenham]") {
  const LineAlgorithm& bresenham = line_algorithms[2];
  REQUIRE(bresenham.name == "bresenham");
  check_ties_on_seeded_lines(bresenham, 5, [](const Line& line, glm::ivec2) {
    return smaller_major_endpoint(line);  // whichever end the drawing starts from
  });
}

TEST_CASE("midpoint breaks ties toward p0, the endpoint it starts from",
          "[01_lines][step6][lines][ties][midpoint]") {
  const LineAlgorithm& midpoint = line_algorithms[3];
  REQUIRE(midpoint.name == "midpoint");
  check_ties_on_seeded_lines(midpoint, 6, [](const Line&, glm::ivec2 from) { return from; });
}

TEST_CASE("midpoint draws what Bresenham draws when p0 has the smaller major coordinate",
          "[01_lines][step6][lines][ties][midpoint]") {
  // Their decision variables are the same up to sign and offset; only the walking direction
  // differs, because Bresenham sorts the endpoints and midpoint starts from p0.
  const LineAlgorithm& bresenham = line_algorithms[2];
  const LineAlgorithm& midpoint = line_algorithms[3];
  int lines_with_ties = 0;
  for (Line line : seeded_canvas_lines()) {
    if (smaller_major_endpoint(line) != line.p0) std::swap(line.p0, line.p1);
    CAPTURE(line.p0.x, line.p0.y, line.p1.x, line.p1.y);
    CHECK(drawn_pixels(midpoint, line.p0, line.p1) == drawn_pixels(bresenham, line.p0, line.p1));
    const auto exact = exact_line_pixels(line.p0, line.p1);
    if (std::any_of(exact.begin(), exact.end(), [](const auto& p) { return p.tie; })) {
      ++lines_with_ties;
    }
  }
  CHECK(lines_with_ties == 685);  // so the equality above is tested where it matters
}

TEST_CASE("line algorithms disagree with round-half-up at a pinned number of tie steps",
          "[01_lines][step3][lines][ties]") {
  // Every step of the 2000 seeded lines (drawn p0 -> p1) where the true line passes exactly
  // halfway between two pixels; the numbers below were measured with this test and are quoted
  // in the chapter's README.
  std::int64_t tie_steps = 0;
  std::map<std::string_view, std::int64_t> disagreements;
  for (const Line& line : seeded_canvas_lines()) {
    std::vector<PixelSet> drawings;
    for (const LineAlgorithm& algorithm : line_algorithms) {
      drawings.push_back(drawn_pixels(algorithm, line.p0, line.p1));
    }
    for (const ExactLinePixel& exact : exact_line_pixels(line.p0, line.p1)) {
      if (!exact.tie) continue;
      ++tie_steps;
      for (std::size_t i = 0; i < line_algorithms.size(); ++i) {
        if (drawings[i].count({exact.pixel.x, exact.pixel.y}) == 0) {
          ++disagreements[line_algorithms[i].name];
        }
      }
    }
  }
  CHECK(tie_steps == 1605);
  CHECK(disagreements["gambetta"] == 370);
  CHECK(disagreements["dda"] == 399);
  CHECK(disagreements["bresenham"] == 810);
  CHECK(disagreements["midpoint"] == 827);
}

TEST_CASE("Bresenham draws a line from -2^30 to 2^30 across a 64x64 canvas column by column",
          "[01_lines][step5][lines][bresenham]") {
  const LineAlgorithm& bresenham = line_algorithms[2];
  REQUIRE(bresenham.name == "bresenham");
  SECTION("(-2^30, 5) to (2^30, 9) crosses the canvas on row 7") {
    PixelSet row7;
    for (int x = 0; x < canvas_size; ++x) row7.emplace(x, 7);
    for (const bool reversed : {false, true}) {
      const glm::ivec2 a(-two_30, 5), b(two_30, 9);
      const Canvas canvas = reversed ? draw(bresenham, b, a) : draw(bresenham, a, b);
      CHECK(written_pixels(canvas) == row7);
      CHECK(overdrawn_pixels(canvas).empty());
      CHECK(canvas.outside_writes() == 0);
    }
  }
  SECTION("a steep line whose first visible step is a tie starts on the right pixel") {
    // x = 3 + 57 (y + 2^30) / 2^31: 31.5 exactly at y = 0 (a tie, broken toward (3, -2^30)),
    // then just above 31.5.
    PixelSet expected{{31, 0}};
    for (int y = 1; y < canvas_size; ++y) expected.emplace(32, y);
    const Canvas canvas = draw(bresenham, {60, two_30}, {3, -two_30});
    CHECK(written_pixels(canvas) == expected);
    CHECK(canvas.outside_writes() == 0);
  }
  SECTION("a line above the canvas draws nothing and writes nothing outside it") {
    const Canvas canvas = draw(bresenham, {-two_30, 100}, {two_30, 100});
    CHECK(written_pixels(canvas).empty());
    CHECK(canvas.outside_writes() == 0);
  }
  SECTION("random lines with endpoints up to 2^30 away show exactly the exact visible pixels") {
    Random random(30);
    for (int trial = 0; trial < 500; ++trial) {
      const int far = two_30;
      const Line line = trial % 2 == 0
                            ? random_line(random, -far, far)
                            : Line{{random.integer(-far, far), random.integer(-far, far)},
                                   {random.integer(0, 63), random.integer(0, 63)}};
      CAPTURE(line.p0.x, line.p0.y, line.p1.x, line.p1.y);
      const Axes axes = axes_of(line);
      const glm::ivec2 toward = smaller_major_endpoint(line);
      const std::int64_t first =
          std::max<std::int64_t>(0, std::min(axes.major(line.p0), axes.major(line.p1)));
      const std::int64_t last = std::min<std::int64_t>(
          canvas_size - 1, std::max(axes.major(line.p0), axes.major(line.p1)));
      PixelSet expected;
      std::int64_t steps_on_canvas = 0;
      for (std::int64_t major = first; major <= last; ++major, ++steps_on_canvas) {
        const glm::ivec2 p =
            tie_broken_toward(exact_line_pixel_at(line.p0, line.p1, major), axes, toward);
        if (on_canvas(p)) expected.emplace(p.x, p.y);
      }
      const Canvas canvas = draw(bresenham, line.p0, line.p1);
      const PixelSet pixels = written_pixels(canvas);
      CHECK(pixels == expected);
      CHECK(overdrawn_pixels(canvas).empty());
      // It walks only the steps whose major coordinate is on the canvas, and writes only on it.
      CHECK(canvas.outside_writes() == 0);
      CHECK(static_cast<std::int64_t>(pixels.size()) <= steps_on_canvas);
    }
  }
}
