#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <limits>

#include "chapters/08_fast_exact/simd.hpp"
#include "chapters/08_fast_exact/test_triangles.hpp"

using tri::Triangle;
using tri::ch08::LaneWidth;

TEST_CASE("Every lane of the lane test agrees with direct evaluation, in 32 and 64 bits",
          "[08_fast_exact][step5]") {
  tri::testing::Random random(55);
  int tested32 = 0;
  tri::ch08::testing::for_each_random_setup(
      random, 3000, 40, 40, [&](int i, const tri::ch08::TriangleSetup& setup) {
        const auto& r = setup.range;
        for (int k = 0; k < 8; ++k) {
          const int x = random.integer(r.min.x, r.max.x), y = random.integer(r.min.y, r.max.y);
          for (const int lanes : {4, 8}) {
            for (const LaneWidth width : {LaneWidth::bits32, LaneWidth::bits64}) {
              if (width == LaneWidth::bits32 && !tri::ch08::fits_32_bit_lanes(setup)) continue;
              tested32 += width == LaneWidth::bits32;
              const auto result = tri::ch08::lane_test(setup, x, y, width, lanes);
              for (int lane = 0; lane < 8; ++lane) {
                INFO("triangle " << i << " pixel " << x + lane << "," << y << " of " << lanes);
                const bool expected =
                    lane < lanes && x + lane <= r.max.x && setup.covers(x + lane, y);
                REQUIRE(result[lane] == expected);
              }
            }
          }
        }
      });
  CHECK(tested32 > 10000);
}

TEST_CASE("32-bit lanes are chosen only when every value the lanes form fits in 32 bits",
          "[08_fast_exact][step5]") {
  // Triangles up to 4096 pixels across, half of them exactly at the 1024-pixel limit, anywhere
  // near a large canvas: whenever 32-bit lanes are chosen, the largest edge value over the range
  // widened by 7 columns and 1 row (it sits at one of the corners) must fit.
  tri::testing::Random random(56);
  int chosen = 0;
  for (int i = 0; i < 20000; ++i) {
    const double extent = random.integer(0, 1) == 0 ? 1024.0 : random.real(1, 4096);
    const double cx = random.real(-600, 2600), cy = random.real(-600, 2600);
    Triangle t;
    for (auto& v : t) {
      v = {tri::ch08::testing::grid_coordinate(random, cx, cx + extent),
           tri::ch08::testing::grid_coordinate(random, cy, cy + extent)};
    }
    if (i % 3 == 0) t[1] = {t[0].x + extent, t[0].y - extent};  // the full extent on both axes
    const auto setup = tri::ch08::setup_triangle(t, 4096, 4096);
    if (!setup || !tri::ch08::fits_32_bit_lanes(*setup)) continue;
    ++chosen;
    const std::int64_t columns = setup->range.max.x - setup->range.min.x + 7;
    const std::int64_t rows = setup->range.max.y - setup->range.min.y + 1;
    for (const auto& edge : setup->edges) {
      for (const std::int64_t dx : {std::int64_t{0}, columns}) {
        for (const std::int64_t dy : {std::int64_t{0}, rows}) {
          INFO("triangle " << i << ": " << t[0].x << "," << t[0].y << " " << t[1].x << "," << t[1].y
                           << " " << t[2].x << "," << t[2].y);
          const std::int64_t v = edge.at(dx, dy);
          REQUIRE(v <= std::numeric_limits<std::int32_t>::max());
          REQUIRE(v >= std::numeric_limits<std::int32_t>::min());
        }
      }
    }
  }
  CHECK(chosen > 5000);
}

TEST_CASE("A triangle within one 8x8 block skips the blocks, one beyond it does not",
          "[08_fast_exact][step5]") {
  const auto small = tri::ch08::setup_triangle({{{1, 1}, {8.5, 1}, {1, 8.5}}}, 32, 32);
  const auto wide = tri::ch08::setup_triangle({{{1, 1}, {9, 1}, {1, 8}}}, 32, 32);
  REQUIRE(small);
  REQUIRE(wide);
  CHECK(tri::ch08::fits_one_block(*small));
  CHECK_FALSE(tri::ch08::fits_one_block(*wide));
}
