#include "chapters/09_anti_aliasing/area_oracle.hpp"
#include "chapters/07_exact_coverage/jittered_mesh.hpp"

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <stdexcept>

#include "common/random.hpp"
#include "tests/support/pixels.hpp"

namespace tri::ch09 {

namespace {

Fraction sum_of_coverages(const Triangle& t) {
  Fraction sum = 0;
  for (const auto& p : exact_coverages(t)) sum = sum + p.coverage;
  return sum;
}

// A vertex on the 1/256 grid: whole pixels plus k/256.
glm::dvec2 on_grid(int x, int x_256ths, int y, int y_256ths) {
  return {x + x_256ths / 256.0, y + y_256ths / 256.0};
}

}  // namespace

TEST_CASE("A triangle that contains the pixel square covers all of it", "[09_anti_aliasing][step1]") {
  const Triangle t = {{{-3, -3}, {5, -3}, {-3, 5}}};
  CHECK(exact_coverage(t, {0, 0}) == Fraction(1));
  CHECK(exact_coverage(t, {10, 10}) == Fraction(0));
}

TEST_CASE("Hand-computed coverages: half a pixel, a corner, a small triangle inside",
          "[09_anti_aliasing][step1]") {
  // The diagonal of pixel (0, 0) from corner to corner: exactly half.
  CHECK(exact_coverage({{{-0.5, -0.5}, {0.5, -0.5}, {-0.5, 0.5}}}, {0, 0}) == Fraction(1, 2));
  // The hypotenuse x + y = 1 passes the corner (0.5, 0.5): pixel (0, 0) is whole, (1, 0) half,
  // (1, 1) untouched but for that corner.
  const Triangle big = {{{-0.5, -0.5}, {1.5, -0.5}, {-0.5, 1.5}}};
  CHECK(exact_coverage(big, {0, 0}) == Fraction(1));
  CHECK(exact_coverage(big, {1, 0}) == Fraction(1, 2));
  CHECK(exact_coverage(big, {0, 1}) == Fraction(1, 2));
  CHECK(exact_coverage(big, {1, 1}) == Fraction(0));
  // A triangle inside one pixel covers its own area: legs 1/4 and 1/2 -> 1/16.
  CHECK(exact_coverage({{{0, 0}, {0.25, 0}, {0, 0.5}}}, {0, 0}) == Fraction(1, 16));
  // The line y = x through the pixel's centre halves it.
  CHECK(exact_coverage({{{-2, -2}, {2, 2}, {2, -2}}}, {0, 0}) == Fraction(1, 2));
}

TEST_CASE("The coverage does not depend on the winding or the order of the vertices",
          "[09_anti_aliasing][step1]") {
  const std::array<glm::dvec2, 3> v = {on_grid(0, 37, 0, 11), on_grid(3, 200, 1, 5),
                                       on_grid(1, 3, 2, 255)};
  for (int y = -1; y <= 3; ++y) {
    for (int x = -1; x <= 4; ++x) {
      const Fraction first = exact_coverage({{v[0], v[1], v[2]}}, {x, y});
      for (const Triangle& order : tri::testing::vertex_orders(v)) {
        INFO("pixel " << x << ", " << y);
        CHECK(exact_coverage(order, {x, y}) == first);
      }
    }
  }
}

TEST_CASE("The coverages of all pixels add up to exactly the triangle's area",
          "[09_anti_aliasing][step1]") {
  Random random(20261123);
  for (int trial = 0; trial < 200; ++trial) {
    Triangle t;
    for (auto& v : t)
      v = {random.integer(-1024, 3072) / 256.0, random.integer(-1024, 3072) / 256.0};
    INFO("trial " << trial);
    CHECK(sum_of_coverages(t) == exact_area(t));
  }
}

TEST_CASE("In a mesh the coverages around an interior pixel add up to exactly one",
          "[09_anti_aliasing][step1]") {
  // A 6x6 grid of 2-pixel cells from (0, 0), inner vertices jittered on the 1/256 grid.
  const auto mesh = ch07::jittered_mesh(6, 6, {0, 0}, 2, 0.15, 7);
  for (int y = 1; y < 12; ++y) {
    for (int x = 1; x < 12; ++x) {
      Fraction sum = 0;
      for (const auto& t : mesh) sum = sum + exact_coverage(t, {x, y});
      INFO("pixel " << x << ", " << y << ": " << sum.text());
      CHECK(sum == Fraction(1));
    }
  }
}

TEST_CASE("A zero-area triangle covers nothing", "[09_anti_aliasing][step1]") {
  CHECK(exact_coverage({{{-1, -1}, {1, 1}, {3, 3}}}, {0, 0}) == Fraction(0));
  CHECK(exact_coverages({{{-1, -1}, {1, 1}, {3, 3}}}).empty());
  CHECK(exact_coverages({{{0.5, 0.5}, {0.5, 0.5}, {0.5, 0.5}}}).empty());
}

TEST_CASE("The oracle refuses vertices off the 1/256 grid or beyond its range",
          "[09_anti_aliasing][step1]") {
  CHECK_THROWS_AS(exact_coverage({{{0.1, 0}, {1, 0}, {0, 1}}}, {0, 0}), std::invalid_argument);
  CHECK_THROWS_AS(exact_coverage({{{1e6, 0}, {1, 0}, {0, 1}}}, {0, 0}), std::invalid_argument);
  CHECK_THROWS_AS(exact_coverage({{{NAN, 0}, {1, 0}, {0, 1}}}, {0, 0}), std::invalid_argument);
}

TEST_CASE("coverage_16 rounds 65535 times the coverage, halves up, clamped to [0, 1]",
          "[09_anti_aliasing][step1]") {
  CHECK(coverage_16(Fraction(0)) == 0);
  CHECK(coverage_16(Fraction(1)) == 65535);
  CHECK(coverage_16(Fraction(1, 2)) == 32768);  // 32767.5 rounds up
  CHECK(coverage_16(Fraction(1, 65535)) == 1);
  CHECK(coverage_16(Fraction(1, 131070)) == 1);  // exactly half a unit rounds up
  CHECK(coverage_16(Fraction(1, 131071)) == 0);
  CHECK(coverage_16(Fraction(3, 2)) == 65535);
  CHECK(coverage_16(Fraction(-1, 2)) == 0);
}

}  // namespace tri::ch09
