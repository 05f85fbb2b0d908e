#include <catch2/catch.hpp>

#include "chapters/07_exact_coverage/coverage_oracle.hpp"
#include "tests/support/pixels.hpp"

using tri::Triangle;
using tri::testing::PixelSet;

namespace {

PixelSet oracle_pixels(const Triangle& t, int width = 16, int height = 16) {
  tri::Canvas canvas(width, height);
  canvas.enable_write_counts();
  tri::ch07::draw_triangle_oracle(canvas, t, tri::colors::white);
  return tri::testing::written_pixels(canvas);
}

// The same answer asked pixel by pixel, to check draw_triangle_oracle's bounding box.
PixelSet covered_pixels(const Triangle& t, int width = 16, int height = 16) {
  PixelSet set;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      if (tri::ch07::oracle_covers(t, {x, y})) set.emplace(x, y);
    }
  }
  return set;
}

PixelSet intersection(const PixelSet& a, const PixelSet& b) {
  PixelSet both;
  for (const auto& p : a) {
    if (b.contains(p)) both.insert(p);
  }
  return both;
}

constexpr double unit = 1.0 / 256;

}  // namespace

TEST_CASE("Top and left edges are recognised with y up and counter-clockwise winding",
          "[07_exact_coverage][step1]") {
  using tri::ch07::is_top_left_edge;
  CHECK(is_top_left_edge({4, 4}, {0, 4}));        // horizontal, right to left: top
  CHECK_FALSE(is_top_left_edge({0, 0}, {4, 0}));  // horizontal, left to right: bottom
  CHECK(is_top_left_edge({0, 4}, {0, 0}));        // going down: left
  CHECK(is_top_left_edge({3, 4}, {0, 0}));
  CHECK_FALSE(is_top_left_edge({0, 0}, {0, 4}));  // going up: right
  CHECK_FALSE(is_top_left_edge({4, 0}, {0, 4}));
}

TEST_CASE("The oracle covers a right triangle with legs on pixel centres by the top-left rule",
          "[07_exact_coverage][step3]") {
  // Inside: (1,1) (1,2) (2,1). On the left leg x = 0: (0,1) (0,2) (0,3) are kept; the bottom leg
  // and the hypotenuse are bottom and right edges; the vertices (0,0) and (0,4) touch one.
  const PixelSet expected{{0, 1}, {0, 2}, {0, 3}, {1, 1}, {1, 2}, {2, 1}};
  const Triangle ccw{{{0, 0}, {4, 0}, {0, 4}}};
  const Triangle cw{{{0, 0}, {0, 4}, {4, 0}}};
  CHECK(oracle_pixels(ccw) == expected);
  CHECK(oracle_pixels(cw) == expected);
  CHECK(covered_pixels(ccw) == expected);
}

TEST_CASE("The oracle covers a rectangle split in two exactly once per pixel",
          "[07_exact_coverage][step1]") {
  const Triangle lower{{{0, 0}, {4, 0}, {4, 3}}};
  const Triangle upper{{{0, 0}, {4, 3}, {0, 3}}};
  const PixelSet a = oracle_pixels(lower), b = oracle_pixels(upper);
  CHECK(intersection(a, b).empty());
  PixelSet both = a;
  both.insert(b.begin(), b.end());
  // Left column x = 0 and top row y = 3 belong to the rectangle; right column and bottom row not.
  PixelSet expected;
  for (int y = 1; y <= 3; ++y) {
    for (int x = 0; x <= 3; ++x) expected.emplace(x, y);
  }
  CHECK(both == expected);
  // By hand: the lower triangle keeps the centres strictly below the diagonal 3x = 4y.
  CHECK(a == PixelSet{{2, 1}, {3, 1}, {3, 2}});
}

TEST_CASE("a 1/256-pixel triangle covers a centre exactly on its horizontal top edge",
          "[07_exact_coverage][step3]") {
  const Triangle t{{{5 + unit, 5}, {5 - unit, 5}, {5, 5 - unit}}};
  CHECK(oracle_pixels(t) == PixelSet{{5, 5}});
}

TEST_CASE("a 1/256-pixel triangle does not cover a centre exactly on its horizontal bottom edge",
          "[07_exact_coverage][step1]") {
  const Triangle t{{{5 - unit, 5}, {5 + unit, 5}, {5, 5 + unit}}};
  CHECK(oracle_pixels(t).empty());
}

TEST_CASE("a 1/256-pixel triangle covers a centre strictly inside it",
          "[07_exact_coverage][step1]") {
  const Triangle t{{{5 - unit, 5 - unit}, {5 + unit, 5 - unit}, {5, 5 + unit}}};
  CHECK(oracle_pixels(t) == PixelSet{{5, 5}});
  const Triangle beside{{{5.5 - unit, 5 - unit}, {5.5 + unit, 5 - unit}, {5.5, 5 + unit}}};
  CHECK(oracle_pixels(beside).empty());
}

TEST_CASE("Edges through pixel centres give each centre to exactly one of two neighbours",
          "[07_exact_coverage][step3]") {
  // Two triangles on either side of a shared edge a-b through several centres.
  struct Case {
    glm::dvec2 a, b, left, right;
  };
  const Case cases[] = {
      {{0, 0}, {8, 8}, {0, 8}, {8, 0}},    // slope 1
      {{1, 0}, {5, 8}, {0, 8}, {8, 0}},    // slope 2
      {{0, 1}, {12, 5}, {0, 9}, {12, 0}},  // slope 1/3
      {{0, 8}, {8, 0}, {0, 0}, {9, 9}},    // slope -1
      {{3, 0}, {3, 8}, {0, 5}, {9, 4}},    // vertical
      {{0, 4}, {8, 4}, {5, 9}, {5, 0}},    // horizontal
  };
  for (const Case& c : cases) {
    const PixelSet one = oracle_pixels({{c.a, c.b, c.left}});
    const PixelSet two = oracle_pixels({{c.b, c.a, c.right}});
    CHECK(intersection(one, two).empty());
    // Every centre strictly between a and b on the shared edge is covered by one of them.
    const glm::dvec2 d = c.b - c.a;
    int centres = 0;
    for (int k = 1; k < 64; ++k) {
      const glm::dvec2 p = c.a + d * (k / 64.0);
      if (p.x != std::floor(p.x) || p.y != std::floor(p.y)) continue;
      const std::pair<int, int> pixel(static_cast<int>(p.x), static_cast<int>(p.y));
      CHECK((one.contains(pixel) != two.contains(pixel)));
      ++centres;
    }
    CHECK(centres >= 3);
  }
  // By hand for slope 1: the diagonal's inner centres run downwards in the lower triangle, a
  // left edge there, so (1,1) .. (7,7) belong to it.
  const PixelSet lower = oracle_pixels({{{8, 8}, {0, 0}, {8, 0}}});
  for (int k = 1; k <= 7; ++k) CHECK(lower.contains({k, k}));
}

TEST_CASE("The oracle covers nothing for zero-area triangles", "[07_exact_coverage][step1]") {
  CHECK(oracle_pixels({{{3, 3}, {3, 3}, {3, 3}}}).empty());
  CHECK(oracle_pixels({{{1, 1}, {5, 5}, {3, 3}}}).empty());
  CHECK(oracle_pixels({{{1, 4}, {9, 4}, {5, 4}}}).empty());
  CHECK(oracle_pixels({{{0.1, 0.2}, {0.3, 0.6}, {0.2, 0.4}}}).empty());  // as doubles, not quite
}

TEST_CASE("The oracle gives the same pixels for all six vertex orders",
          "[07_exact_coverage][step1]") {
  tri::testing::Random random(5);
  for (int i = 0; i < 300; ++i) {
    const Triangle t = tri::testing::random_real_triangle(random, -4, 20);
    const PixelSet expected = oracle_pixels(t);
    for (const Triangle& order : tri::testing::vertex_orders(t)) {
      REQUIRE(oracle_pixels(order) == expected);
    }
    REQUIRE(covered_pixels(t) == expected);
  }
}

TEST_CASE("The oracle handles vertices far outside the canvas", "[07_exact_coverage][step1]") {
  // A triangle with huge vertices that contains the whole 16x16 canvas.
  const Triangle huge{{{-1e9, -1e9}, {1e9, -1e9}, {0, 1e9}}};
  CHECK(oracle_pixels(huge).size() == 256);
  const Triangle away{{{1e7, 1e7}, {2e7, 1e7}, {1e7, 2e7}}};
  CHECK(oracle_pixels(away).empty());
}
