#include <catch2/catch.hpp>

#include <cstdint>
#include <limits>

#include "chapters/08_fast_exact/incremental.hpp"
#include "chapters/08_fast_exact/test_triangles.hpp"

using tri::Triangle;

TEST_CASE("The incremental walk visits every candidate pixel once with the direct edge values",
          "[08_fast_exact][step1]") {
  tri::testing::Random random(11);
  tri::ch08::testing::for_each_random_setup(
      random, 600, 24, 19, [&](int, const tri::ch08::TriangleSetup& setup) {
        const auto& r = setup.range;
        int expected_x = r.min.x, expected_y = r.min.y;
        long visits = 0;
        tri::ch08::walk_incremental(
            setup, [&](int x, int y, std::int64_t w0, std::int64_t w1, std::int64_t w2) {
              // Row by row from the bottom, left to right.
              REQUIRE(x == expected_x);
              REQUIRE(y == expected_y);
              const std::int64_t dx = x - r.min.x, dy = y - r.min.y;
              REQUIRE(w0 == setup.edges[0].at(dx, dy));
              REQUIRE(w1 == setup.edges[1].at(dx, dy));
              REQUIRE(w2 == setup.edges[2].at(dx, dy));
              ++visits;
              if (++expected_x > r.max.x) {
                expected_x = r.min.x;
                ++expected_y;
              }
            });
        CHECK(visits == static_cast<long>(r.max.x - r.min.x + 1) * (r.max.y - r.min.y + 1));
      });
}

TEST_CASE("The OR of three values is non-negative exactly when all three are",
          "[08_fast_exact][step2]") {
  constexpr std::int64_t low = std::numeric_limits<std::int64_t>::min();
  constexpr std::int64_t high = std::numeric_limits<std::int64_t>::max();
  const std::int64_t values[] = {0, 1, -1, 2, -2, 255, -256, high, low, low + 1, high - 1};
  for (const std::int64_t a : values) {
    for (const std::int64_t b : values) {
      for (const std::int64_t c : values) {
        CHECK(tri::ch08::inside_all_edges(a, b, c) == (a >= 0 && b >= 0 && c >= 0));
      }
    }
  }
  tri::testing::Random random(3);
  for (int i = 0; i < 100000; ++i) {
    const auto a = static_cast<std::int64_t>(random.next());
    const auto b = static_cast<std::int64_t>(random.next() >> random.integer(0, 63));
    const auto c = -static_cast<std::int64_t>(random.next() >> random.integer(1, 63));
    REQUIRE(tri::ch08::inside_all_edges(a, b, c) == (a >= 0 && b >= 0 && c >= 0));
    REQUIRE(tri::ch08::inside_all_edges(a, b, -c) == (a >= 0 && b >= 0));
  }
}
