// The traps of the chapter's C++ port, each pinned by the correct behaviour: loops that stop one
// short, the commented-out pop_back, and integer loop counters over real coordinates.
#include <vector>

#include <catch2/catch.hpp>

#include "chapters/03_interpolate_fill/algorithms.hpp"
#include "chapters/03_interpolate_fill/test_helpers.hpp"

using namespace tri::ch03;
using namespace tri::ch03::testing;
using Catch::Matchers::Approx;
using tri::Canvas;

namespace {

PixelSet spans_pixels(int first_row, const LeftRightXs& spans) {
  Canvas canvas(16, 16);
  canvas.enable_write_counts();
  draw_spans(canvas, first_row, spans, tri::colors::white);
  return tri::testing::written_pixels(canvas);
}

}  // namespace

TEST_CASE("Trap `i < i1`: every edge array reaches its upper vertex's row",
          "[03_interpolate_fill][traps]") {
  const SortedTriangle t = sort_by_y(hand_triangle[0], hand_triangle[1], hand_triangle[2]);
  const EdgeXs e = interpolate_edges(t, triangle_rows(t));
  CHECK(e.x01.size() == 4);  // rows 0..3, not 0..2
  CHECK(e.x12.size() == 3);  // rows 3..5
  CHECK(e.x02.size() == 6);  // rows 0..5
  CHECK(e.x02.back() == Catch::Detail::Approx(2));
  CHECK(e.x12.back() == Catch::Detail::Approx(2));
}

TEST_CASE("Traps `y < P2.y` and `x < x_right`: the top row and each span's right end are drawn",
          "[03_interpolate_fill][traps]") {
  const PixelSet pixels = fill_pixels(hand_triangle, 16, 16);
  CHECK(pixels.count({2, 5}) == 1);  // row y2, the apex P2
  // The right end of every row: round(x012) = 1, 3, 4, 6, 4, 2 on rows 0..5.
  const int right_ends[] = {1, 3, 4, 6, 4, 2};
  for (int y = 0; y < 6; ++y) {
    CHECK(pixels.count({right_ends[y], y}) == 1);
    CHECK(pixels.count({right_ends[y] + 1, y}) == 0);
  }
}

TEST_CASE("Trap: without the pop_back, x012 is one row too long and every row above P1 shifts",
          "[03_interpolate_fill][traps][pop_back]") {
  const SortedTriangle t = sort_by_y(hand_triangle[0], hand_triangle[1], hand_triangle[2]);
  const EdgeXs e = interpolate_edges(t, triangle_rows(t));
  const std::vector<double> x012 = concatenate_short_sides(e.x01, e.x12);
  std::vector<double> doubled = e.x01;  // the port: pop_back commented out
  doubled.insert(doubled.end(), e.x12.begin(), e.x12.end());

  REQUIRE(doubled.size() == e.x02.size() + 1);
  const std::size_t p1_row = 3;
  for (std::size_t i = 0; i <= p1_row; ++i) CHECK(doubled[i] == Catch::Detail::Approx(x012[i]));
  for (std::size_t i = p1_row + 1; i < e.x02.size(); ++i) CHECK(doubled[i] == x012[i - 1]);

  // Drawn, the upper short side is one row late: rows 4 and 5 reach as far as rows 3 and 4.
  const PixelSet right = spans_pixels(0, choose_left_right(e.x02, x012));
  const PixelSet wrong = spans_pixels(0, choose_left_right(e.x02, doubled));
  CHECK(minus(wrong, right) == PixelSet{{5, 4}, {6, 4}, {3, 5}, {4, 5}});
  CHECK(minus(right, wrong).empty());
}

TEST_CASE("Trap: the port's one-short Interpolate hides its missing pop_back",
          "[03_interpolate_fill][traps][pop_back]") {
  // Dropping each array's last value mimics `i < i1`. Then x01 no longer ends on row y1, so
  // x01 + x12 happens to have the right length and values, and only the top row is lost.
  const SortedTriangle t = sort_by_y(hand_triangle[0], hand_triangle[1], hand_triangle[2]);
  EdgeXs e = interpolate_edges(t, triangle_rows(t));
  const std::vector<double> x012 = concatenate_short_sides(e.x01, e.x12);
  for (auto* array : {&e.x01, &e.x12, &e.x02}) array->pop_back();
  std::vector<double> port_x012 = e.x01;
  port_x012.insert(port_x012.end(), e.x12.begin(), e.x12.end());
  CHECK(port_x012.size() == e.x02.size());
  CHECK_THAT(port_x012, Approx(std::vector<double>(x012.begin(), x012.end() - 1)).margin(1e-12));
}

TEST_CASE("Trap: span ends are rounded to the nearest column, not cut by an int loop counter",
          "[03_interpolate_fill][traps][rounding]") {
  // The port's `for (int x = x_left; x < x_right; x++)`: the int truncates the start, and the
  // strict comparison drops a right end that is a whole number.
  const auto port_columns = [](double x_left, double x_right) {
    std::vector<int> columns;
    for (int x = static_cast<int>(x_left); x < x_right; ++x) columns.push_back(x);
    return columns;
  };
  CHECK(port_columns(2.7, 5.2) == std::vector<int>{2, 3, 4, 5});  // 2 is 0.7 outside
  CHECK(port_columns(2.0, 5.0) == std::vector<int>{2, 3, 4});     // 5 is on the edge
  CHECK(spans_pixels(0, {{2.7}, {5.2}}) == PixelSet{{3, 0}, {4, 0}, {5, 0}});
  CHECK(spans_pixels(0, {{2.0}, {5.0}}) == PixelSet{{2, 0}, {3, 0}, {4, 0}, {5, 0}});
}

TEST_CASE("Trap: real vertices are rounded to the nearest pixel centre, also below zero",
          "[03_interpolate_fill][traps][rounding]") {
  const tri::TriangleAlgorithm& fill = triangle_algorithms()[0];
  const auto registered_pixels = [&](const tri::Triangle& triangle) {
    Canvas canvas(16, 16);
    canvas.enable_write_counts();
    fill.draw(canvas, triangle, tri::colors::white);
    return tri::testing::written_pixels(canvas);
  };
  CHECK(registered_pixels({{{1.4, 0.4}, {5.6, 2.6}, {2.2, 4.6}}}) ==
        fill_pixels(hand_triangle, 16, 16));
  // -0.6 is nearest to -1; an int conversion would truncate it towards zero, to 0.
  const PixelSet below_zero = registered_pixels({{{-0.6, 0.2}, {6.4, -0.3}, {5.7, 6.5}}});
  CHECK(below_zero == fill_pixels({{{-1, 0}, {6, 0}, {6, 7}}}, 16, 16));
  CHECK(below_zero != fill_pixels({{{0, 0}, {6, 0}, {5, 6}}}, 16, 16));
}
