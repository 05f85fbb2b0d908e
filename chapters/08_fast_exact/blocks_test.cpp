#include <catch2/catch.hpp>

#include <cstdint>
#include <map>
#include <utility>

#include "chapters/08_fast_exact/blocks.hpp"
#include "chapters/08_fast_exact/test_triangles.hpp"

using tri::Triangle;
using tri::ch05::PixelBox;
using tri::ch08::BlockCoverage;

namespace {

// How many pixels of the block the setup covers, evaluated directly.
int covered_in(const tri::ch08::TriangleSetup& setup, const PixelBox& block) {
  int n = 0;
  for (int y = block.min.y; y <= block.max.y; ++y) {
    for (int x = block.min.x; x <= block.max.x; ++x) n += setup.covers(x, y);
  }
  return n;
}

int area(const PixelBox& r) {
  return (r.max.x - r.min.x + 1) * (r.max.y - r.min.y + 1);
}

// How often each pixel (x, y) was visited.
using Visits = std::map<std::pair<int, int>, int>;

// Counts one visit of every pixel of the box.
void count_visits(const PixelBox& box, Visits& seen) {
  for (int y = box.min.y; y <= box.max.y; ++y) {
    for (int x = box.min.x; x <= box.max.x; ++x) ++seen[{x, y}];
  }
}

void require_each_visited_once(const Visits& seen) {
  for (const auto& [pixel, count] : seen) REQUIRE(count == 1);
}

// Calls visit(setup) for the triangles both tiling tests walk: 300 of every shape on 70x53.
template <class Visit>
void for_each_tiling_setup(std::uint64_t seed, Visit&& visit) {
  tri::testing::Random random(seed);
  tri::ch08::testing::for_each_random_setup(
      random, 300, 70, 53, [&](int, const tri::ch08::TriangleSetup& setup) { visit(setup); });
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
          const int x0 = random.integer(r.min.x, r.max.x), y0 = random.integer(r.min.y, r.max.y);
          const PixelBox block{{x0, y0},
                               {random.integer(x0, r.max.x), random.integer(y0, r.max.y)}};
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
  for_each_tiling_setup(45, [&](const tri::ch08::TriangleSetup& setup) {
    Visits seen;
    tri::ch08::for_each_block(setup, [&](const PixelBox& block, BlockCoverage coverage) {
      CHECK((block.min.x - setup.range.min.x) % 8 == 0);
      CHECK((block.min.y - setup.range.min.y) % 8 == 0);
      CHECK(block.max.x - block.min.x < 8);
      CHECK(coverage == tri::ch08::classify_block(setup, block));
      count_visits(block, seen);
    });
    REQUIRE(static_cast<int>(seen.size()) == area(setup.range));
    require_each_visited_once(seen);
  });
}

TEST_CASE("Runs of inside blocks and partial blocks hold every covered pixel exactly once",
          "[08_fast_exact][step4]") {
  for_each_tiling_setup(46, [&](const tri::ch08::TriangleSetup& setup) {
    Visits seen;
    int covered_in_runs = 0, covered_in_partials = 0, run_pixels = 0;
    tri::ch08::for_each_block_run(
        setup,
        [&](const PixelBox& run) {
          count_visits(run, seen);
          run_pixels += area(run);
          covered_in_runs += covered_in(setup, run);
        },
        [&](const PixelBox& block) {
          count_visits(block, seen);
          covered_in_partials += covered_in(setup, block);
        });
    require_each_visited_once(seen);
    CHECK(covered_in_runs == run_pixels);
    CHECK(covered_in_runs + covered_in_partials == covered_in(setup, setup.range));
  });
}
