#include "chapters/04_scanline/lower_half.hpp"

#include <cstdlib>
#include <map>

#include <catch2/catch.hpp>

#include "chapters/04_scanline/scanline_test_support.hpp"

namespace {

using namespace tri::ch04;
using namespace tri::ch04::testing;
using namespace tri::testing;
using tri::Canvas;

// Step 3 has its own colours, so it gets its own reader.
PixelSet boundary_points(glm::ivec2 a, glm::ivec2 b, glm::ivec2 c) {
  Canvas canvas(200, 200);
  canvas.enable_write_counts();
  tri::ch04::draw_lower_half_boundary_points(canvas, a, b, c);
  CHECK(canvas.outside_writes() == 0);
  return written_pixels(canvas);
}

// Breaks in one boundary of step 3: consecutive rows whose points are not neighbours (they move
// by more than one column), and the pixels a connected line would need to close them.
struct Gaps {
  int breaks = 0;
  int missing_pixels = 0;
};

Gaps gaps_along(glm::ivec2 a, glm::ivec2 b, glm::ivec2 c, bool boundary_a) {
  const auto t = sort_by_y(a, b, c);
  Gaps gaps;
  for (int y = t.p0.y + 1; y <= t.p1.y; ++y) {
    const auto below = lower_half_ends(t, y - 1), here = lower_half_ends(t, y);
    const auto step = std::llabs(boundary_a ? here.a - below.a : here.b - below.b);
    if (step > 1) {
      ++gaps.breaks;
      gaps.missing_pixels += static_cast<int>(step - 1);
    }
  }
  return gaps;
}

}  // namespace

TEST_CASE("Boundary B of the lower half stops short of t1 because of the +1 height",
          "[04_scanline][step3][trap]") {
  // Red triangle: t0 = (10,70), t1 = (70,80), t2 = (50,160). At row 80, B is 10/11 of the way.
  const auto t = sort_by_y(red_triangle[0], red_triangle[1], red_triangle[2]);
  const auto top = lower_half_ends(t, 80);
  CHECK(top.b == 64);  // 10 + 60 * 10 / 11 = 64.5, truncated; t1.x is 70
  CHECK(top.a == 14);  // 10 + 40 * 10 / 90 = 14.4, truncated
  const auto bottom = lower_half_ends(t, 70);
  CHECK(bottom.a == 10);
  CHECK(bottom.b == 10);
}

TEST_CASE("Step 3 draws exactly the two boundary points of every lower-half row",
          "[04_scanline][step3]") {
  for (const auto& triangle : tinyrenderer_triangles) {
    const auto [a, b, c] = triangle.vertices;
    const auto t = sort_by_y(a, b, c);
    PixelSet expected;
    for (int y = t.p0.y; y <= t.p1.y; ++y) {
      const auto ends = lower_half_ends(t, y);
      expected.emplace(static_cast<int>(ends.a), y);
      expected.emplace(static_cast<int>(ends.b), y);
    }
    CHECK(boundary_points(a, b, c) == expected);
  }
}

TEST_CASE("Step 3 leaves gaps where a boundary moves more than one column per row",
          "[04_scanline][step3]") {
  // {triangle index, boundary A?} -> {breaks, missing pixels}, counted on the article's image.
  const std::map<std::pair<int, bool>, std::pair<int, int>> expected{
      {{0, true}, {0, 0}}, {{0, false}, {10, 44}},  // red: B is the shallow bottom edge
      {{1, true}, {0, 0}}, {{1, false}, {0, 0}},    // white: both boundaries steep
      {{2, true}, {6, 6}}, {{2, false}, {10, 44}},  // green: both shallow
  };
  int total_breaks = 0;
  for (int i = 0; i < 3; ++i) {
    const auto [a, b, c] = tinyrenderer_triangles[i].vertices;
    for (const bool boundary_a : {true, false}) {
      const Gaps gaps = gaps_along(a, b, c, boundary_a);
      INFO("triangle " << i << (boundary_a ? " boundary A" : " boundary B"));
      CHECK(std::pair(gaps.breaks, gaps.missing_pixels) == expected.at({i, boundary_a}));
      total_breaks += gaps.breaks;
    }
  }
  CHECK(total_breaks == 26);
}

TEST_CASE("Step 4 fills each lower-half row from boundary A to boundary B",
          "[04_scanline][step4]") {
  const int expected_counts[] = {286, 1288, 218};
  for (int i = 0; i < 3; ++i) {
    const auto [a, b, c] = tinyrenderer_triangles[i].vertices;
    const auto t = sort_by_y(a, b, c);
    PixelSet expected;
    for (int y = t.p0.y; y <= t.p1.y; ++y) {
      const auto ends = lower_half_ends(t, y);
      add_row(expected, y, static_cast<int>(std::min(ends.a, ends.b)),
              static_cast<int>(std::max(ends.a, ends.b)));
    }
    const PixelSet filled = pixels_of(fill_lower_half, a, b, c);
    CHECK(filled == expected);
    CHECK(filled.size() == static_cast<std::size_t>(expected_counts[i]));
  }
}

TEST_CASE("With t0.y == t1.y the lower half is the single pixel t0, whichever vertex that is",
          "[04_scanline][traps][step4][division-by-zero][order]") {
  // The +1 makes the segment height 1, so the one row runs B from t0 toward t1 by 0/1.
  CHECK(pixels_of(fill_lower_half, {0, 0}, {4, 0}, {2, 3}) == PixelSet{{0, 0}});
  CHECK(pixels_of(fill_lower_half, {4, 0}, {0, 0}, {2, 3}) == PixelSet{{4, 0}});
  CHECK(boundary_points({0, 0}, {4, 0}, {2, 3}) == PixelSet{{0, 0}});
}

TEST_CASE("With t1.y == t2.y the lower half misses t1 on the top edge",
          "[04_scanline][step4][division-by-zero][order]") {
  // t0 = (2,0); the top edge runs from (0,3) to (4,3). B reaches only 3/4 of the way to t1.
  PixelSet expected{{2, 0}, {2, 1}};
  add_row(expected, 2, 1, 3);
  PixelSet left_first = expected, right_first = expected;
  add_row(left_first, 3, 1, 4);   // t1 = (0,3): the row stops at x = 1
  add_row(right_first, 3, 0, 3);  // t1 = (4,3): the row stops at x = 3
  CHECK(pixels_of(fill_lower_half, {2, 0}, {0, 3}, {4, 3}) == left_first);
  CHECK(pixels_of(fill_lower_half, {2, 0}, {4, 3}, {0, 3}) == right_first);
}

TEST_CASE("Steps 3 and 4 draw nothing when all three vertices share a row",
          "[04_scanline][traps][step3][step4][division-by-zero]") {
  // The article would compute 0/0 for alpha and cast the NaN to int: undefined behaviour.
  CHECK(boundary_points({0, 2}, {5, 2}, {3, 2}).empty());
  CHECK(pixels_of(fill_lower_half, {0, 2}, {5, 2}, {3, 2}).empty());
  CHECK(pixels_of(fill_lower_half, {7, 7}, {7, 7}, {7, 7}).empty());
}

TEST_CASE("Steps 3 and 4 stay on the canvas for vertices at plus or minus 1e7 and 2^30",
          "[04_scanline][step3][safety]") {
  for (const int far : {10'000'000, 1 << 30}) {
    // Every canvas row lies in the lower half, with A far to the left and B far to the right.
    const glm::ivec2 a{-far, -far}, b{far, far / 2}, c{0, far};
    Canvas filled(64, 64);
    filled.enable_write_counts();
    fill_lower_half(filled, a, b, c, tri::colors::white);
    CHECK(filled.outside_writes() == 0);
    for (const auto count : filled.write_counts()) CHECK(count == 1);
    CHECK(boundary_points(a, b, c).empty());  // both boundaries pass beside the canvas
  }
}
