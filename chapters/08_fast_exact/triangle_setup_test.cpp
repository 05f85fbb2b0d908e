#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include "chapters/07_exact_coverage/coverage_oracle.hpp"
#include "chapters/07_exact_coverage/fixed_point.hpp"
#include "chapters/08_fast_exact/test_triangles.hpp"
#include "chapters/08_fast_exact/triangle_setup.hpp"

using tri::Triangle;
using tri::ch08::TriangleSetup;
using tri::testing::PixelSet;

namespace {

// Every pixel of the canvas the setup covers, evaluated directly.
PixelSet covered_by(const std::optional<TriangleSetup>& setup) {
  PixelSet pixels;
  if (!setup) return pixels;
  for (int y = setup->range.min.y; y <= setup->range.max.y; ++y) {
    for (int x = setup->range.min.x; x <= setup->range.max.x; ++x) {
      if (setup->covers(x, y)) pixels.emplace(x, y);
    }
  }
  return pixels;
}

PixelSet oracle_pixels(const Triangle& t, int width, int height) {
  tri::Canvas canvas(width, height);
  canvas.enable_write_counts();
  tri::ch07::draw_triangle_oracle(canvas, t, tri::colors::white);
  return tri::testing::written_pixels(canvas);
}

// Asserts an edge function's value and steps (as one array, which Catch prints on a failure).
void check_edge(const tri::ch08::EdgeFunction& edge, std::int64_t value, std::int64_t step_x,
                std::int64_t step_y) {
  CHECK(std::array{edge.value, edge.step_x, edge.step_y} == std::array{value, step_x, step_y});
}

}  // namespace

TEST_CASE("floor_to_integer is std::floor for every kind of double it meets",
          "[08_fast_exact][triangle_setup]") {
  using tri::ch08::floor_to_integer;
  for (const double x : {0.0, -0.0, 0.5, -0.5, 1.0, -1.0, 2.999999, -2.000001, 1e-300, -1e-300,
                         274877906944.5, -274877906944.5, 274877906943.99997}) {
    INFO(x);
    CHECK(floor_to_integer(x) == static_cast<std::int64_t>(std::floor(x)));
  }
  tri::testing::Random random(8);
  for (int i = 0; i < 100000; ++i) {
    const double numerator = random.real(-3e11, 3e11);  // drawn first on every compiler
    const double x = numerator / std::ldexp(1.0, random.integer(0, 40));
    REQUIRE(floor_to_integer(x) == static_cast<std::int64_t>(std::floor(x)));
  }
}

TEST_CASE("snap_to_256ths gives exactly chapter 07's snap_to_subpixel with 8 bits",
          "[08_fast_exact][triangle_setup]") {
  tri::testing::Random random(256);
  const auto same = [](glm::dvec2 p) {
    const tri::ch07::SubpixelPoint ours = tri::ch08::snap_to_256ths(p);
    const tri::ch07::SubpixelPoint theirs = tri::ch07::snap_to_subpixel(p, 8);
    return ours.x == theirs.x && ours.y == theirs.y;
  };
  // Exact halves of a 1/256 step round up on both sides of zero, as chapter 07 does.
  for (const double v : {0.5 / 256, -0.5 / 256, 1.5 / 256, -1.5 / 256, 0.49999999 / 256,
                         -0.50000001 / 256, 0.49999999999999994 / 256, -0.5000000000000001 / 256,
                         1073741824.0, -1073741824.0, 0.0, -0.0}) {
    INFO(v);
    CHECK(same({v, -v}));
  }
  for (int i = 0; i < 100000; ++i) {
    const double scale = std::ldexp(1.0, random.integer(-10, 30));
    REQUIRE(same({random.real(-1, 1) * scale, random.real(-1, 1) * scale}));
  }
}

TEST_CASE("A hand-checked triangle on pixel centres follows the top-left rule",
          "[08_fast_exact][triangle_setup]") {
  // (0,0), (4,0), (0,4): the bottom edge is not top-left (centres on it are out), the left edge
  // is (in), the hypotenuse is a right edge (out).
  const Triangle t{{{0, 0}, {4, 0}, {0, 4}}};
  const PixelSet expected{{0, 1}, {1, 1}, {2, 1}, {0, 2}, {1, 2}, {0, 3}};
  CHECK(covered_by(tri::ch08::setup_triangle(t, 8, 8)) == expected);
  CHECK(covered_by(tri::ch08::setup_triangle({{t[0], t[2], t[1]}}, 8, 8)) == expected);
  // Shifted by 1/256 to the right: the left edge leaves the centres at x = 0.
  const Triangle shifted{{{1.0 / 256, 0}, {4 + 1.0 / 256, 0}, {1.0 / 256, 4}}};
  CHECK(covered_by(tri::ch08::setup_triangle(shifted, 8, 8)) ==
        PixelSet{{1, 1}, {2, 1}, {3, 1}, {1, 2}, {2, 2}, {1, 3}});
}

TEST_CASE("edge steps are the vertex differences and values are whole-pixel edge functions",
          "[08_fast_exact][triangle_setup]") {
  // Counter-clockwise (0,0), (4,0), (0,4) in 1/256 units; the origin is pixel (0, 0).
  const auto setup = tri::ch08::setup_triangle({{{0, 0}, {4, 0}, {0, 4}}}, 8, 8);
  REQUIRE(setup);
  const auto& [e0, e1, e2] = setup->edges;
  // Edge b -> c = (4,0) -> (0,4): E = (-1024)(py) - (1024)(px - 1024), at (0,0) E = 2^20 =
  // 4096 * 256; a right edge, so its exact zeros must fail: value 4096 - 1.
  check_edge(e0, 4095, -1024, -1024);
  // Edge c -> a = (0,4) -> (0,0), a left edge through the origin: E = 0 and no bias.
  check_edge(e1, 0, 1024, 0);
  // Edge a -> b = (0,0) -> (4,0), a bottom edge through the origin: E = 0, bias -1.
  check_edge(e2, -1, 0, 1024);
}

TEST_CASE("Direct evaluation of the setup equals the oracle for every shape of triangle",
          "[08_fast_exact][triangle_setup]") {
  tri::testing::Random random(808);
  for (int i = 0; i < 4000; ++i) {
    const Triangle t =
        tri::ch08::testing::random_triangle(random, tri::ch08::testing::shape_number(i), 40);
    INFO(i << ": " << t[0].x << "," << t[0].y << " " << t[1].x << "," << t[1].y << " " << t[2].x
           << "," << t[2].y);
    REQUIRE(covered_by(tri::ch08::setup_triangle(t, 40, 33)) == oracle_pixels(t, 40, 33));
  }
}

TEST_CASE("A triangle around the whole canvas has clamped edges that pass everywhere",
          "[08_fast_exact][triangle_setup]") {
  const double far = 1073741824.0;
  const auto setup = tri::ch08::setup_triangle({{{-far, -far}, {far, -far}, {0, far}}}, 20, 10);
  REQUIRE(setup);
  for (const auto& edge : setup->edges) {
    check_edge(edge, tri::ch08::edge_value_limit, 0, 0);
  }
  CHECK(covered_by(setup).size() == 200);
}

TEST_CASE("Zero area, a miss of the canvas and an edge far beyond it give no setup",
          "[08_fast_exact][triangle_setup]") {
  CHECK_FALSE(tri::ch08::setup_triangle({{{0, 0}, {0, 0}, {0, 0}}}, 8, 8));
  CHECK_FALSE(tri::ch08::setup_triangle({{{1, 1}, {9, 9}, {5, 5}}}, 8, 8));
  CHECK_FALSE(tri::ch08::setup_triangle({{{20, 20}, {30, 20}, {20, 30}}}, 8, 8));
  // Candidate pixels cover the canvas, but the canvas lies 2^23 pixels outside one edge, whose
  // value at the origin is beyond edge_value_limit.
  const double far = 1073741824.0;
  const Triangle below{{{-far, -far}, {far, -far}, {far, far - 16777216.0}}};
  CHECK(oracle_pixels(below, 8, 8).empty());
  CHECK_FALSE(tri::ch08::setup_triangle(below, 8, 8));
}

TEST_CASE("Clipping a setup keeps exactly its pixels inside the clip",
          "[08_fast_exact][triangle_setup]") {
  tri::testing::Random random(5);
  tri::ch08::testing::for_each_random_setup(
      random, 500, 32, 32, [&](int, const tri::ch08::TriangleSetup& setup) {
        const int x0 = random.integer(0, 31), y0 = random.integer(0, 31);
        const tri::ch05::PixelBox clip{{x0, y0}, {random.integer(x0, 31), random.integer(y0, 31)}};
        PixelSet expected;
        for (const auto& p : covered_by(setup)) {
          if (p.first >= clip.min.x && p.first <= clip.max.x && p.second >= clip.min.y &&
              p.second <= clip.max.y) {
            expected.insert(p);
          }
        }
        const auto clipped = tri::ch08::clip_setup(setup, clip);
        REQUIRE(covered_by(clipped) == expected);
        if (clipped) {
          CHECK(clipped->range.min.x >= clip.min.x);
          CHECK(clipped->range.max.y <= clip.max.y);
        }
      });
}
