#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "chapters/07_exact_coverage/exact_orientation.hpp"
#include "chapters/07_exact_coverage/int128.hpp"
#include "tests/support/pixels.hpp"

using tri::Int128;
using tri::ch07::exact_orientation;
using tri::ch07::exact_orientation_slow_path;

namespace {

// What a first attempt would write: the determinant in doubles, sign taken as is.
int naive_orientation(glm::dvec2 a, glm::dvec2 b, glm::dvec2 p) {
  const double d = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
  return (d > 0) - (d < 0);
}

}  // namespace

TEST_CASE("Orientation is +1 to the left, -1 to the right and 0 on the line",
          "[07_exact_coverage][step2]") {
  const glm::dvec2 a(0, 0), b(4, 2);
  CHECK(exact_orientation(a, b, {0, 1}) == 1);
  CHECK(exact_orientation(a, b, {0, -1}) == -1);
  CHECK(exact_orientation(a, b, {2, 1}) == 0);
  CHECK(exact_orientation(a, b, {-6, -3}) == 0);
  CHECK(exact_orientation(a, a, {3, 7}) == 0);
}

TEST_CASE("Orientation is exact on points a double determinant cannot separate",
          "[07_exact_coverage][step2]") {
  // On the line through (0.5, 0.25) with slope 1/2, and one unit in the last place above it.
  const glm::dvec2 a(0.5, 0.25), b(8.5, 4.25);
  CHECK(exact_orientation(a, b, {4.5, 2.25}) == 0);
  CHECK(exact_orientation(a, b, {4.5, std::nextafter(2.25, 3.0)}) == 1);
  CHECK(exact_orientation(a, b, {4.5, std::nextafter(2.25, 2.0)}) == -1);
}

TEST_CASE("Orientation is exact for subnormal coordinates", "[07_exact_coverage][step2]") {
  const double tiny = std::numeric_limits<double>::denorm_min();  // 2^-1074
  // The determinant is 2^-2148: far below what a double holds, yet positive.
  CHECK(naive_orientation({tiny, 0}, {0, tiny}, {0, 0}) == 0);
  CHECK(exact_orientation({tiny, 0}, {0, tiny}, {0, 0}) == 1);
  CHECK(exact_orientation({0, tiny}, {tiny, 0}, {0, 0}) == -1);
  CHECK(exact_orientation({tiny, tiny}, {2 * tiny, 2 * tiny}, {3 * tiny, 3 * tiny}) == 0);
}

TEST_CASE("Orientation is exact for coordinates whose products overflow doubles",
          "[07_exact_coverage][step2]") {
  // a -> b runs down the diagonal y = x; (1, 0) is 2e300 units of area to its left.
  const glm::dvec2 a(1e300, 1e300), b(-1e300, -1e300);
  CHECK(naive_orientation(a, b, {1, 0}) == 0);  // inf - inf is NaN, and NaN compares false
  CHECK(exact_orientation(a, b, {1, 0}) == 1);
  CHECK(exact_orientation(a, b, {0, 1}) == -1);
  CHECK(exact_orientation(a, b, {7, 7}) == 0);
  const double max = std::numeric_limits<double>::max();
  CHECK(exact_orientation({-max, -max}, {max, max}, {0, 1}) == 1);
}

TEST_CASE("Orientation agrees with 128-bit integers on near-collinear points of a fine grid",
          "[07_exact_coverage][step2]") {
  // Coordinates k / 2^40 with |k| < 2^21: the determinant times 2^80 is an exact 128-bit integer.
  tri::testing::Random random(7);
  int naive_wrong = 0;
  for (int i = 0; i < 20000; ++i) {
    const std::int64_t ax = random.integer(-1 << 20, 1 << 20),
                       ay = random.integer(-1 << 20, 1 << 20);
    const std::int64_t dx = random.integer(-1 << 10, 1 << 10),
                       dy = random.integer(-1 << 10, 1 << 10);
    const std::int64_t t = random.integer(-1000, 1000);
    // p sits on the line through a with direction d, nudged by at most one grid unit.
    const std::int64_t px = ax + t * dx + random.integer(-1, 1);
    const std::int64_t py = ay + t * dy + random.integer(-1, 1);
    const std::int64_t bx = ax + dx, by = ay + dy;
    const Int128 det = Int128(bx - ax) * (py - ay) - Int128(by - ay) * (px - ax);
    const int expected = (det > 0) - (det < 0);
    const double unit = 0x1p-40;
    const glm::dvec2 a(ax * unit, ay * unit), b(bx * unit, by * unit), p(px * unit, py * unit);
    REQUIRE(exact_orientation(a, b, p) == expected);
    REQUIRE(exact_orientation_slow_path(a, b, p) == expected);
    naive_wrong += naive_orientation(a, b, p) != expected;
  }
  // Exact inputs, small integers: doubles get these right too, which is what the fast path uses.
  CHECK(naive_wrong == 0);
}

TEST_CASE("Orientation is antisymmetric and cyclic on random doubles of every magnitude",
          "[07_exact_coverage][step2]") {
  tri::testing::Random random(11);
  for (int i = 0; i < 20000; ++i) {
    const auto coordinate = [&] {
      // One draw a statement: a call's arguments are evaluated in an order the language leaves
      // open.
      const int exponent = random.integer(-1070, 1020);
      return std::ldexp(random.real(-1, 1), exponent);
    };
    // Braces evaluate left to right, so every compiler draws the same points.
    const glm::dvec2 a{coordinate(), coordinate()}, b{coordinate(), coordinate()},
        p{coordinate(), coordinate()};
    const int s = exact_orientation(a, b, p);
    REQUIRE(exact_orientation(b, a, p) == -s);
    REQUIRE(exact_orientation(b, p, a) == s);
    REQUIRE(exact_orientation(p, a, b) == s);
    REQUIRE(exact_orientation_slow_path(a, b, p) == s);
  }
}

TEST_CASE("Orientation's fast and exact paths agree near the line where doubles round",
          "[07_exact_coverage][step2]") {
  // Points one ulp off a line with awkward slope: the filter must hand these to the exact path.
  tri::testing::Random random(3);
  for (int i = 0; i < 20000; ++i) {
    const glm::dvec2 a = tri::testing::random_real_point(random, -100, 100);
    const glm::dvec2 b = tri::testing::random_real_point(random, -100, 100);
    const double t = random.real(-2, 3);
    glm::dvec2 p = a + t * (b - a);
    p.y = std::nextafter(p.y, random.integer(0, 1) ? 1e9 : -1e9);
    REQUIRE(exact_orientation(a, b, p) == exact_orientation_slow_path(a, b, p));
  }
}
