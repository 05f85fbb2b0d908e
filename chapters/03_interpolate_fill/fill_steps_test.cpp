// Chapter 03's steps one by one, on a small triangle checked by hand: P0 (1,0), P1 (6,3),
// P2 (2,5). Its short sides have slopes 5/3 and -2 (x per row), its tall side 1/5.
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <catch2/catch.hpp>

#include "chapters/03_interpolate_fill/test_helpers.hpp"

using namespace tri::ch03;
using namespace tri::ch03::testing;
using Catch::Matchers::Approx;
using tri::Canvas;

namespace {

std::vector<double> values(std::initializer_list<double> list) {
  return list;
}

}  // namespace

TEST_CASE("Step 1 sorts the vertices by increasing y whatever their order",
          "[03_interpolate_fill][step1][steps][sort]") {
  std::array<int, 3> order{0, 1, 2};
  do {
    const SortedTriangle t =
        sort_by_y(hand_triangle[order[0]], hand_triangle[order[1]], hand_triangle[order[2]]);
    CHECK(t.p0 == glm::ivec2(1, 0));
    CHECK(t.p1 == glm::ivec2(6, 3));
    CHECK(t.p2 == glm::ivec2(2, 5));
  } while (std::next_permutation(order.begin(), order.end()));
}

TEST_CASE("Step 1 keeps vertices of equal y in the order they came",
          "[03_interpolate_fill][step1][steps][sort]") {
  const SortedTriangle a = sort_by_y({4, 0}, {0, 0}, {2, 2});
  CHECK((a.p0 == glm::ivec2(4, 0) && a.p1 == glm::ivec2(0, 0)));
  const SortedTriangle b = sort_by_y({0, 0}, {2, 2}, {4, 0});
  CHECK((b.p0 == glm::ivec2(0, 0) && b.p1 == glm::ivec2(4, 0)));
}

TEST_CASE("Step 2 gives each edge one x per row, both end rows included",
          "[03_interpolate_fill][step2][steps][interpolate]") {
  const SortedTriangle t = sort_by_y(hand_triangle[0], hand_triangle[1], hand_triangle[2]);
  const EdgeXs e = interpolate_edges(t, triangle_rows(t));
  CHECK_THAT(e.x01, Approx(values({1, 1 + 5 / 3.0, 1 + 10 / 3.0, 6})).margin(1e-12));
  CHECK_THAT(e.x12, Approx(values({6, 4, 2})).margin(1e-12));
  CHECK_THAT(e.x02, Approx(values({1, 1.2, 1.4, 1.6, 1.8, 2})).margin(1e-12));
  // The first value of each array is its lower vertex's x exactly.
  CHECK(e.x01.front() == 1);
  CHECK(e.x12.front() == 6);
  CHECK(e.x02.front() == 1);
}

TEST_CASE("Step 2 on a clipped row range keeps each edge's rows in that range",
          "[03_interpolate_fill][step2][steps][interpolate][clip]") {
  const SortedTriangle t = sort_by_y(hand_triangle[0], hand_triangle[1], hand_triangle[2]);
  const EdgeXs e = interpolate_edges(t, {2, 4});
  CHECK_THAT(e.x01, Approx(values({1 + 10 / 3.0, 6})).margin(1e-12));  // rows 2..3
  CHECK_THAT(e.x12, Approx(values({6, 4})).margin(1e-12));             // rows 3..4
  CHECK_THAT(e.x02, Approx(values({1.4, 1.6, 1.8})).margin(1e-12));    // rows 2..4
  CHECK(interpolate_edges(t, {4, 9}).x01.empty());                     // above P1
  CHECK(interpolate_edges(t, {-3, 1}).x12.empty());                    // below P1
}

TEST_CASE("Step 2 gives a flat edge the single x of its first end",
          "[03_interpolate_fill][step2][steps][interpolate]") {
  const SortedTriangle t = sort_by_y({0, 0}, {4, 0}, {2, 2});
  const EdgeXs e = interpolate_edges(t, triangle_rows(t));
  CHECK(e.x01 == values({0}));
}

TEST_CASE("Step 2 refuses to allocate more rows than a canvas has",
          "[03_interpolate_fill][step2][steps][interpolate][safety]") {
  const SortedTriangle t = sort_by_y({0, -(1 << 30)}, {5, 0}, {0, 1 << 30});
  CHECK_THROWS_AS(interpolate_edges(t, triangle_rows(t)), std::length_error);
  const EdgeXs clipped = interpolate_edges(t, visible_rows(t, 64));
  CHECK(clipped.x02.size() == 64);
  CHECK(clipped.x01.size() == 1);  // only row 0, where P1 is
  CHECK(clipped.x12.size() == 64);
}

TEST_CASE("Step 3 makes x012 exactly as long as x02",
          "[03_interpolate_fill][step3][steps][concatenate]") {
  tri::testing::Random random(301);
  for (int i = 0; i < 1000; ++i) {
    const Vertices v = random_vertices(random, -40, 40);
    const SortedTriangle t = sort_by_y(v[0], v[1], v[2]);
    EdgeXs e = interpolate_edges(t, triangle_rows(t));
    const std::size_t rows = static_cast<std::size_t>(t.p2.y - t.p0.y + 1);
    CHECK(e.x02.size() == rows);
    const auto x012 = concatenate_short_sides(std::move(e.x01), e.x12);
    CHECK(x012.size() == rows);
  }
}

TEST_CASE("Step 3 drops x01's copy of row y1 and keeps x12's",
          "[03_interpolate_fill][step3][steps][concatenate]") {
  const SortedTriangle t = sort_by_y(hand_triangle[0], hand_triangle[1], hand_triangle[2]);
  EdgeXs e = interpolate_edges(t, triangle_rows(t));
  const auto x012 = concatenate_short_sides(e.x01, e.x12);
  CHECK_THAT(x012, Approx(values({1, 1 + 5 / 3.0, 1 + 10 / 3.0, 6, 4, 2})).margin(1e-12));
  CHECK(x012[3] == 6);  // row y1 is x12's exact first value
  // When clipping left only one of the short sides there is no shared row to drop.
  CHECK(concatenate_short_sides({}, values({3, 4})) == values({3, 4}));
  CHECK(concatenate_short_sides(values({3, 4}), {}) == values({3, 4}));
}

TEST_CASE("Step 4 compares x02 and x012 at the middle row",
          "[03_interpolate_fill][step4][steps][left-right]") {
  CHECK(middle_row_index(6) == 3);
  CHECK(middle_row_index(5) == 2);
  CHECK(middle_row_index(1) == 0);
  // The hand triangle: at row 3, x02 = 1.6 < x012 = 6, so the tall side is on the left.
  const LeftRightXs hand_spans =
      choose_left_right(values({1, 1.2, 1.4, 1.6, 1.8, 2}), values({1, 2.5, 4, 6, 4, 2}));
  CHECK(hand_spans.x_left == values({1, 1.2, 1.4, 1.6, 1.8, 2}));
  // A flat top (2,0) (0,2) (4,2): x02 = {2,3,4}, x012 = {2,1,0}; 3 > 1, the tall side is right.
  const LeftRightXs flat_top = choose_left_right(values({2, 3, 4}), values({2, 1, 0}));
  CHECK(flat_top.x_left == values({2, 1, 0}));
  CHECK(flat_top.x_right == values({2, 3, 4}));
}

TEST_CASE("Step 4 looks past a middle row where both sides meet",
          "[03_interpolate_fill][step4][steps][left-right]") {
  // (0,0) (4,0) (2,1) is two rows tall: its middle row (index 1) is the apex, x = 2 on both.
  const SortedTriangle t = sort_by_y({0, 0}, {4, 0}, {2, 1});
  EdgeXs e = interpolate_edges(t, triangle_rows(t));
  auto x012 = concatenate_short_sides(std::move(e.x01), e.x12);
  REQUIRE(e.x02 == values({0, 2}));
  REQUIRE(x012 == values({4, 2}));
  // The book's "else" would put x012 = {4, 2} on the left and row 0 would draw nothing.
  const LeftRightXs spans = choose_left_right(e.x02, x012);
  CHECK(spans.x_left == values({0, 2}));
  CHECK(spans.x_right == values({4, 2}));
}

TEST_CASE("Step 5 draws from the nearest column of x_left to that of x_right",
          "[03_interpolate_fill][step5][steps][spans]") {
  Canvas canvas(10, 4);
  canvas.enable_write_counts();
  // Row 0 rounds 2.7 -> 3 and 5.2 -> 5; row 1 rounds halves up: 2.5 -> 3, 4.5 -> 5;
  // row 2's ends round to the same column; row 3's left end rounds past its right end.
  draw_spans(canvas, 0, {values({2.7, 2.5, 6.4, 6.6}), values({5.2, 4.5, 6.2, 6.4})},
             tri::colors::white);
  CHECK(tri::testing::written_pixels(canvas) ==
        PixelSet{{3, 0}, {4, 0}, {5, 0}, {3, 1}, {4, 1}, {5, 1}, {6, 2}});
}

TEST_CASE("Step 5 clips rows and spans to the canvas before drawing",
          "[03_interpolate_fill][step5][steps][spans][safety]") {
  Canvas canvas(4, 3);
  canvas.enable_write_counts();
  // Rows -2..3 of which 0..2 exist; ends far beyond both sides of the canvas.
  draw_spans(canvas, -2, {values({0, 0, -1e9, 2, -0.4, 0}), values({3, 3, 1e9, 9.6, 0.4, 3})},
             tri::colors::white);
  CHECK(tri::testing::written_pixels(canvas) ==
        PixelSet{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {2, 1}, {3, 1}, {0, 2}});
  CHECK(canvas.outside_writes() == 0);
  CHECK(nearest_column(-1e300, 4) == -1);
  CHECK(nearest_column(1e300, 4) == 4);
  CHECK(nearest_column(std::nan(""), 4) == -1);
}
