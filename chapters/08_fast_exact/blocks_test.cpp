#include <catch2/catch.hpp>

#include <map>
#include <utility>

#include "chapters/08_fast_exact/blocks.hpp"
#include "chapters/08_fast_exact/test_triangles.hpp"

using tri::Triangle;
using tri::ch07::PixelRange;
using tri::ch08::BlockCoverage;

namespace {

// How many pixels of the block the setup covers, evaluated directly.
int covered_in(const tri::ch08::TriangleSetup& setup, const PixelRange& block) {
  int n = 0;
  for (int y = block.first_y; y <= block.last_y; ++y) {
    for (int x = block.first_x; x <= block.last_x; ++x) n += setup.covers(x, y);
  }
  return n;
}

int area(const PixelRange& r) {
  return (r.last_x - r.first_x + 1) * (r.last_y - r.first_y + 1);
}

}  // namespace

TEST_CASE("An accepted block is covered everywhere and a rejected one nowhere",
          "[08_fast_exact][step4]") {
  tri::testing::Random random(44);
  int counts[3] = {0, 0, 0};
  tri::ch08::testing::for_each_random_setup(
      random, 1500, 48, 45, [&](int, const tri::ch08::TriangleSetup& setup) {
        // Blocks of every size, anywhere in the range (not just the 8x8 grid).
        for (int k = 0; k < 20; ++k) {
          const auto& r = setup.range;
          const int x0 = random.integer(r.first_x, r.last_x),
                    y0 = random.integer(r.first_y, r.last_y);
          const PixelRange block{x0, random.integer(x0, r.last_x), y0,
                                 random.integer(y0, r.last_y)};
          const BlockCoverage coverage = tri::ch08::classify_block(setup, block);
          ++counts[static_cast<int>(coverage)];
          if (coverage == BlockCoverage::inside) REQUIRE(covered_in(setup, block) == area(block));
          if (coverage == BlockCoverage::outside) REQUIRE(covered_in(setup, block) == 0);
        }
      });
  // All three answers occur.
  CHECK(counts[0] > 100);
  CHECK(counts[1] > 100);
  CHECK(counts[2] > 100);
}

TEST_CASE("The blocks tile the candidate pixels exactly once, 8x8 from the range's corner",
          "[08_fast_exact][step4]") {
  tri::testing::Random random(45);
  tri::ch08::testing::for_each_random_setup(
      random, 300, 70, 53, [&](int, const tri::ch08::TriangleSetup& setup) {
        std::map<std::pair<int, int>, int> seen;
        tri::ch08::for_each_block(setup, [&](const PixelRange& block, BlockCoverage coverage) {
          CHECK((block.first_x - setup.range.first_x) % 8 == 0);
          CHECK((block.first_y - setup.range.first_y) % 8 == 0);
          CHECK(block.last_x - block.first_x < 8);
          CHECK(coverage == tri::ch08::classify_block(setup, block));
          for (int y = block.first_y; y <= block.last_y; ++y) {
            for (int x = block.first_x; x <= block.last_x; ++x) ++seen[{x, y}];
          }
        });
        REQUIRE(static_cast<int>(seen.size()) == area(setup.range));
        for (const auto& [pixel, count] : seen) REQUIRE(count == 1);
      });
}

TEST_CASE("Runs of inside blocks and partial blocks hold every covered pixel exactly once",
          "[08_fast_exact][step4]") {
  tri::testing::Random random(46);
  tri::ch08::testing::for_each_random_setup(
      random, 300, 70, 53, [&](int, const tri::ch08::TriangleSetup& setup) {
        std::map<std::pair<int, int>, int> seen;
        int covered_in_runs = 0, covered_in_partials = 0, run_pixels = 0;
        const auto visit = [&](const PixelRange& r) {
          for (int y = r.first_y; y <= r.last_y; ++y) {
            for (int x = r.first_x; x <= r.last_x; ++x) ++seen[{x, y}];
          }
        };
        tri::ch08::for_each_block_run(
            setup,
            [&](const PixelRange& run) {
              visit(run);
              run_pixels += area(run);
              covered_in_runs += covered_in(setup, run);
            },
            [&](const PixelRange& block) {
              visit(block);
              covered_in_partials += covered_in(setup, block);
            });
        for (const auto& [pixel, count] : seen) REQUIRE(count == 1);
        CHECK(covered_in_runs == run_pixels);
        CHECK(covered_in_runs + covered_in_partials == covered_in(setup, setup.range));
      });
}
