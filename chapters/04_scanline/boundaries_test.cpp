#include "chapters/04_scanline/boundaries.hpp"

#include <catch2/catch.hpp>

#include "chapters/04_scanline/lower_half.hpp"
#include "chapters/04_scanline/scanline_fills.hpp"
#include "chapters/04_scanline/scanline_test_support.hpp"

namespace {

using tri::ch04::sort_by_y;
using tri::ch04::truncated_boundary_x;
using tri::ch04::testing::red_triangle;
using tri::ch04::testing::tinyrenderer_triangles;

// The article's arithmetic for one boundary: the fraction in float, the float product cut to an
// int by Vec2i's constructor.
int article_float_x(glm::ivec2 start, glm::ivec2 end, int step, int steps) {
  const float fraction = static_cast<float>(step) / static_cast<float>(steps);
  return start.x + static_cast<int>(static_cast<float>(end.x - start.x) * fraction);
}

}  // namespace

TEST_CASE("Sorting by y puts the vertices bottom to top for all six orders",
          "[04_scanline][step2]") {
  for (const auto& triangle : tinyrenderer_triangles) {
    const auto [a, b, c] = triangle.vertices;
    const auto expected = sort_by_y(a, b, c);
    REQUIRE(expected.p0.y < expected.p1.y);
    REQUIRE(expected.p1.y < expected.p2.y);
    for (const auto& order : tri::testing::vertex_orders(a, b, c)) {
      const auto sorted = sort_by_y(order[0], order[1], order[2]);
      CHECK(sorted.p0 == expected.p0);
      CHECK(sorted.p1 == expected.p1);
      CHECK(sorted.p2 == expected.p2);
    }
  }
  const auto sorted = sort_by_y(red_triangle[0], red_triangle[1], red_triangle[2]);
  CHECK(sorted.p0 == glm::ivec2(10, 70));
  CHECK(sorted.p1 == glm::ivec2(70, 80));
  CHECK(sorted.p2 == glm::ivec2(50, 160));
}

TEST_CASE("Sorting keeps vertices of equal y in the order they were passed",
          "[04_scanline][step2]") {
  const auto one = sort_by_y({4, 0}, {0, 0}, {2, 3});
  CHECK(one.p0 == glm::ivec2(4, 0));
  CHECK(one.p1 == glm::ivec2(0, 0));
  const auto other = sort_by_y({0, 0}, {4, 0}, {2, 3});
  CHECK(other.p0 == glm::ivec2(0, 0));
  CHECK(other.p1 == glm::ivec2(4, 0));
}

TEST_CASE("A boundary's x is truncated toward its start vertex, not rounded",
          "[04_scanline][step2][int-cast]") {
  // Red triangle, boundary A from (10,70) to (50,160), row 72: exact x = 10 + 80/90 = 10.89.
  CHECK(truncated_boundary_x(red_triangle[0], red_triangle[1], 2, 90) ==
        10);  // rounding would give 11
  // White triangle, boundary A from (150,1) to (70,180), row 3: exact x = 150 - 160/179 = 149.11.
  CHECK(truncated_boundary_x({150, 1}, {70, 180}, 2, 179) == 150);  // rounding would give 149
  // A whole quotient is exact, in both directions.
  CHECK(truncated_boundary_x({0, 0}, {6, 2}, 1, 2) == 3);
  CHECK(truncated_boundary_x({6, 2}, {2, 5}, 3, 3) == 2);
  CHECK(truncated_boundary_x({6, 2}, {2, 5}, 1, 3) == 5);  // exact 4.67; cut toward 6 gives 5
}

TEST_CASE(
    "The exact quotient gives the article's float span ends on every row of the test triangles",
    "[04_scanline][step2][int-cast]") {
  for (const auto& triangle : tinyrenderer_triangles) {
    const auto [a, b, c] = triangle.vertices;
    const auto t = sort_by_y(a, b, c);
    const int total = t.p2.y - t.p0.y, lower = t.p1.y - t.p0.y, upper = t.p2.y - t.p1.y;
    for (int i = 0; i <= total; ++i) {
      const auto ends = tri::ch04::single_loop_ends(t, i);
      const bool second_half = i > lower || lower == 0;
      CHECK(ends.a == article_float_x(t.p0, t.p2, i, total));
      CHECK(ends.b == (second_half ? article_float_x(t.p1, t.p2, i - lower, upper)
                                   : article_float_x(t.p0, t.p1, i, lower)));
    }
    for (int y = t.p0.y; y <= t.p1.y; ++y) {
      const auto ends = tri::ch04::lower_half_ends(t, y);
      CHECK(ends.a == article_float_x(t.p0, t.p2, y - t.p0.y, total));
      CHECK(ends.b == article_float_x(t.p0, t.p1, y - t.p0.y, lower + 1));
    }
    for (int y = t.p1.y; y <= t.p2.y; ++y) {
      const auto ends = tri::ch04::upper_half_ends(t, y);
      CHECK(ends.a == article_float_x(t.p0, t.p2, y - t.p0.y, total));
      CHECK(ends.b == article_float_x(t.p1, t.p2, y - t.p1.y, upper + 1));
    }
  }
}

TEST_CASE("Float arithmetic can land one pixel short where the exact quotient is whole",
          "[04_scanline][traps][int-cast]") {
  // 7/12 of 108 is exactly 63, but 7/12 in float times 108 is 62.99999 and truncates to 62.
  CHECK(article_float_x({0, 0}, {108, 12}, 7, 12) == 62);
  CHECK(truncated_boundary_x({0, 0}, {108, 12}, 7, 12) == 63);
}

TEST_CASE("Boundary arithmetic stays exact for vertices at plus or minus 2^30",
          "[04_scanline][step2][safety]") {
  constexpr int far = 1 << 30;
  constexpr std::int64_t steps = std::int64_t{1} << 31;
  CHECK(truncated_boundary_x({-far, -far}, {far, far}, steps - 1, steps) == far - 1);
  CHECK(truncated_boundary_x({far, -far}, {-far, far}, steps - 1, steps) == -far + 1);
  CHECK(truncated_boundary_x({-far, -far}, {far, far}, steps, steps) == far);
}
