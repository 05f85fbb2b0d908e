#include <cstdint>

#include <catch2/catch.hpp>

#include "chapters/05_edge_function/cross_product.hpp"
#include "tests/support/pixels.hpp"

using tri::ch05::cross_2d;
using tri::ch05::edge_cross;
using tri::ch05::edge_crosses;
using tri::ch05::edge_crosses_published_bug;
using tri::testing::random_point;

namespace {

__extension__ using Wide = __int128;  // a reference that cannot overflow for ±2^30 inputs

constexpr int two_to_30 = 1 << 30;
constexpr std::int64_t two_to_62 = std::int64_t{1} << 62;

Wide wide_cross(glm::ivec2 a, glm::ivec2 b, glm::ivec2 p) {
  return (Wide{b.x} - a.x) * (Wide{p.y} - a.y) - (Wide{b.y} - a.y) * (Wide{p.x} - a.x);
}

}  // namespace

TEST_CASE("The 2-D cross product is u.x v.y - u.y v.x, positive when v turns left of u",
          "[05_edge_function][step2][cross product]") {
  CHECK(cross_2d({1, 0}, {0, 1}) == 1);   // y up: (0, 1) is left of (1, 0)
  CHECK(cross_2d({0, 1}, {1, 0}) == -1);  // and (1, 0) right of (0, 1)
  CHECK(cross_2d({3, 2}, {1, 4}) == 10);
  CHECK(cross_2d({3, 2}, {6, 4}) == 0);  // parallel
  CHECK(cross_2d({3, 2}, {-6, -4}) == 0);
}

TEST_CASE("AB x AP is positive left of AB, zero on its line and negative right of it",
          "[05_edge_function][step2][cross product]") {
  const glm::ivec2 a(1, 1), b(7, 4);
  CHECK(edge_cross(a, b, {2, 5}) == 6 * 4 - 3 * 1);  // left
  CHECK(edge_cross(a, b, {5, 3}) == 0);              // on the line, between a and b
  CHECK(edge_cross(a, b, {13, 7}) == 0);             // on the line, beyond b
  CHECK(edge_cross(a, b, {6, 1}) == 6 * 0 - 3 * 5);  // right
}

TEST_CASE("The three edge values of any point sum to twice the triangle's signed area",
          "[05_edge_function][step2][cross product]") {
  tri::testing::Random random(5001);
  for (int i = 0; i < 2000; ++i) {
    // ±2^29 keeps the sum itself within 64 bits.
    const glm::ivec2 a = random_point(random, -(1 << 29), 1 << 29);
    const glm::ivec2 b = random_point(random, -(1 << 29), 1 << 29);
    const glm::ivec2 c = random_point(random, -(1 << 29), 1 << 29);
    const glm::ivec2 p = random_point(random, -(1 << 29), 1 << 29);
    const glm::i64vec3 e = edge_crosses(a, b, c, p);
    REQUIRE(e.x + e.y + e.z == edge_cross(a, b, c));
  }
}

TEST_CASE("Edge values are exact for vertices at plus or minus 2^30",
          "[05_edge_function][step2][cross product][huge]") {
  const glm::ivec2 low_left(-two_to_30, -two_to_30), low_right(two_to_30, -two_to_30);
  const glm::ivec2 top_right(two_to_30, two_to_30);
  // The largest magnitude possible: twice the area of half the 2^31 x 2^31 square, 2^62.
  CHECK(edge_cross(low_left, low_right, top_right) == two_to_62);
  CHECK(edge_cross(low_right, low_left, top_right) == -two_to_62);
  // b.x - a.x = 2^31 does not fit in an int: the difference must be taken in 64 bits.
  CHECK(edge_cross({-two_to_30, 0}, {two_to_30, 0}, {0, 1}) == std::int64_t{1} << 31);

  tri::testing::Random random(5002);
  for (int i = 0; i < 5000; ++i) {
    const glm::ivec2 a = random_point(random, -two_to_30, two_to_30);
    const glm::ivec2 b = random_point(random, -two_to_30, two_to_30);
    const glm::ivec2 p = random_point(random, -two_to_30, two_to_30);
    REQUIRE(Wide{edge_cross(a, b, p)} == wide_cross(a, b, p));
  }
}

TEST_CASE("The published edge values are off by BC.x (B.y - A.y) and CA.x (C.y - A.y)",
          "[05_edge_function][step2][cross product][published bug]") {
  tri::testing::Random random(5003);
  for (int i = 0; i < 5000; ++i) {
    const glm::ivec2 a = random_point(random, -two_to_30, two_to_30);
    const glm::ivec2 b = random_point(random, -two_to_30, two_to_30);
    const glm::ivec2 c = random_point(random, -two_to_30, two_to_30);
    const glm::ivec2 p = random_point(random, 0, 16383);  // a canvas pixel
    const glm::i64vec3 right = edge_crosses(a, b, c, p);
    const glm::i64vec3 published = edge_crosses_published_bug(a, b, c, p);
    REQUIRE(published.x == right.x);  // AB x AP is untouched
    REQUIRE(Wide{published.y} == Wide{right.y} + (Wide{c.x} - b.x) * (Wide{b.y} - a.y));
    REQUIRE(Wide{published.z} == Wide{right.z} + (Wide{a.x} - c.x) * (Wide{c.y} - a.y));
  }
}

TEST_CASE("The published bug vanishes when AB is horizontal and CA vertical",
          "[05_edge_function][step2][cross product][published bug]") {
  const glm::ivec2 a(2, 3), b(12, 3), c(2, 9);
  for (int y = 0; y < 16; ++y) {
    for (int x = 0; x < 16; ++x) {
      REQUIRE(edge_crosses_published_bug(a, b, c, {x, y}) == edge_crosses(a, b, c, {x, y}));
    }
  }
}
