// The figures' own arithmetic, and the pixel claims the README reads off them.
#include <string>

#include <catch2/catch.hpp>

#include "chapters/01_lines/lines.hpp"
#include "chapters/02_wireframe/wireframe.hpp"
#include "chapters/03_interpolate_fill/diagram_support.hpp"
#include "chapters/03_interpolate_fill/test_helpers.hpp"

using namespace tri::ch03;
using namespace tri::ch03::testing;
using namespace tri::ch03::figures;

TEST_CASE("Figure labels show at most two decimals and no trailing zeros",
          "[03_interpolate_fill][diagram_support][figures]") {
  CHECK(short_number(8.0 / 3.0) == "2.67");
  CHECK(short_number(1.2) == "1.2");
  CHECK(short_number(6.0) == "6");
  CHECK(short_number(-0.001) == "0");
}

TEST_CASE("centre_in_triangle counts centres on an edge as inside, in either winding",
          "[03_interpolate_fill][diagram_support][figures]") {
  const glm::ivec2 a{0, 0}, b{4, 0}, c{0, 4};
  for (const bool clockwise : {false, true}) {
    const auto inside = [&](glm::ivec2 p) {
      return clockwise ? centre_in_triangle(a, c, b, p) : centre_in_triangle(a, b, c, p);
    };
    CHECK(inside({1, 1}));
    CHECK(inside({2, 2}));  // on the hypotenuse
    CHECK(inside({0, 0}));  // a vertex
    CHECK_FALSE(inside({3, 2}));
    CHECK_FALSE(inside({-1, 0}));
  }
}

TEST_CASE("Step 5's rounded ends reach past the edge at exactly (1,1), (3,1) and (1,2)",
          "[03_interpolate_fill][step5][figures]") {
  const auto [a, b, c] = hand_triangle;
  PixelSet outside;
  for (const auto& p : fill_pixels(hand_triangle, 16, 16)) {
    if (!centre_in_triangle(a, b, c, {p.first, p.second})) outside.insert(p);
  }
  CHECK(outside == PixelSet{{1, 1}, {3, 1}, {1, 2}});
}

TEST_CASE("Figure 7-3's wide edge ties every fourth column: in the fill upright, out flipped",
          "[03_interpolate_fill][diagram_support][figures][outline]") {
  // Canvas coordinates of the 600x600 figure: the book's centred ones plus 300.
  for (const int flip : {1, -1}) {
    const Vertices v{{{100, 300 - 250 * flip}, {500, 300 + 50 * flip}, {320, 300 + 250 * flip}}};
    const PixelSet fill = fill_pixels(v, 600, 600);
    tri::Canvas outline(600, 600);
    outline.enable_write_counts();
    tri::ch02::draw_wireframe_triangle(outline, v[0], v[1], v[2], tri::colors::black);
    int ties = 0;
    for (int x = v[0].x; x <= v[1].x; ++x) {
      glm::ivec2 tie;
      if (!halfway_tie(v[0], v[1], x, tie)) continue;
      ++ties;
      CHECK((x - v[0].x) % 4 == 2);
      CHECK(outline.write_count(tie.x, tie.y) > 0);  // the outline rounds the tie up
      CHECK(fill.count({tie.x, tie.y}) == (flip > 0 ? 1u : 0u));
    }
    CHECK(ties == 100);
  }
}

TEST_CASE("A half-way tie is found on edges given either way round",
          "[03_interpolate_fill][diagram_support][figures]") {
  glm::ivec2 forward, backward;
  REQUIRE(halfway_tie({0, 0}, {4, 3}, 2, forward));
  REQUIRE(halfway_tie({4, 3}, {0, 0}, 2, backward));
  CHECK(forward == glm::ivec2(2, 2));  // y = 1.5 rounds up to 2
  CHECK(backward == forward);
  CHECK_FALSE(halfway_tie({0, 0}, {4, 3}, 1, forward));  // y = 0.75
}

TEST_CASE(
    "Tinyrenderer's green triangle: its 30 outline pixels outside the fill are on the wide edges",
    "[03_interpolate_fill][diagram_support][figures][outline]") {
  const Vertices green{{{180, 150}, {120, 160}, {130, 180}}};
  const PixelSet fill = fill_pixels(green, 200, 200);
  const auto line = [](glm::ivec2 a, glm::ivec2 b) {
    tri::Canvas canvas(200, 200);
    canvas.enable_write_counts();
    tri::ch01::draw_line_gambetta(canvas, a, b, tri::colors::black);
    return tri::testing::written_pixels(canvas);
  };
  const PixelSet wide_a = line(green[0], green[1]), wide_b = line(green[0], green[2]);
  PixelSet outside = minus(wide_a, fill);
  for (const auto& p : minus(wide_b, fill)) outside.insert(p);
  CHECK(outside.size() == 30);
  // The steep edge P1-P2 is drawn as x = f(y), like the fill: none of its pixels is outside.
  CHECK(minus(line(green[1], green[2]), fill).empty());
}
