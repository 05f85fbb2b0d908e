// draw_filled_triangle, the five steps together: exact pixels of small triangles, one span per
// row, the flat and one-row special cases, and independence from the order of the vertices.
#include <algorithm>
#include <array>
#include <map>

#include <catch2/catch.hpp>

#include "chapters/03_interpolate_fill/test_helpers.hpp"

using namespace tri::ch03;
using namespace tri::ch03::testing;
using tri::Canvas;

namespace {

constexpr int side = 32;

// The pixels for every one of the six orders of v; all equal is what the tests expect.
std::array<PixelSet, 6> pixels_in_every_order(Vertices v, int width = side, int height = side) {
  std::array<int, 3> order{0, 1, 2};
  std::array<PixelSet, 6> result;
  for (PixelSet& pixels : result) {
    pixels = fill_pixels({v[order[0]], v[order[1]], v[order[2]]}, width, height);
    std::next_permutation(order.begin(), order.end());
  }
  return result;
}

// True when an edge of v crosses row y exactly halfway between column x and a neighbour.
bool on_halfway_tie(const Vertices& v, int x, int y) {
  for (int e = 0; e < 3; ++e) {
    const glm::ivec2 a = v[e], b = v[(e + 1) % 3];
    if (a.y == b.y || y < std::min(a.y, b.y) || y > std::max(a.y, b.y)) continue;
    // The edge's x at row y is a.x + (b.x - a.x) (y - a.y) / (b.y - a.y); compare 2x with 2x±1.
    const long long dy = b.y - a.y;
    const long long twice_x_times_dy =
        2 * (a.x * dy + (b.x - a.x) * static_cast<long long>(y - a.y));
    if (twice_x_times_dy == (2LL * x + 1) * dy || twice_x_times_dy == (2LL * x - 1) * dy) {
      return true;
    }
  }
  return false;
}

}  // namespace

TEST_CASE("A small hand-checked triangle fills exactly these pixels",
          "[03_interpolate_fill][step6][fill]") {
  // P0 (1,0), P1 (6,3), P2 (2,5). Rows 0..5 have x02 = 1, 1.2, 1.4, 1.6, 1.8, 2 on the left
  // and x012 = 1, 2.67, 4.33, 6, 4, 2 on the right; each end rounds to the nearest column.
  const PixelSet expected{{1, 0},                                  // 1..1
                          {1, 1}, {2, 1}, {3, 1},                  // 1..3
                          {1, 2}, {2, 2}, {3, 2}, {4, 2},          // 1..4
                          {2, 3}, {3, 3}, {4, 3}, {5, 3}, {6, 3},  // 2..6
                          {2, 4}, {3, 4}, {4, 4},                  // 2..4
                          {2, 5}};                                 // 2..2
  for (const PixelSet& pixels : pixels_in_every_order({{{1, 0}, {6, 3}, {2, 5}}})) {
    CHECK(pixels == expected);
  }
}

TEST_CASE("Every row from y0 to y2 has exactly one span, and no other row is drawn",
          "[03_interpolate_fill][step6][fill]") {
  tri::testing::Random random(311);
  for (int i = 0; i < 1000; ++i) {
    const Vertices v = random_vertices(random, 0, side - 1);
    const PixelSet pixels = fill_pixels(v, side, side);
    const int y0 = std::min({v[0].y, v[1].y, v[2].y});
    const int y2 = std::max({v[0].y, v[1].y, v[2].y});
    std::map<int, int> first_x, last_x, count;
    for (const auto& [x, y] : pixels) {
      if (count[y]++ == 0) first_x[y] = x;
      last_x[y] = x;
    }
    CHECK(static_cast<int>(count.size()) == y2 - y0 + 1);
    for (const auto& [y, n] : count) {
      CHECK(y >= y0);
      CHECK(y <= y2);
      CHECK(n == last_x[y] - first_x[y] + 1);  // contiguous: one span
    }
  }
}

TEST_CASE("The three vertices are always filled", "[03_interpolate_fill][step6][fill]") {
  tri::testing::Random random(312);
  for (int i = 0; i < 1000; ++i) {
    const Vertices v = random_vertices(random, 0, side - 1);
    const PixelSet pixels = fill_pixels(v, side, side);
    for (const glm::ivec2 p : v) CHECK(pixels.count({p.x, p.y}) == 1);
  }
}

TEST_CASE("A horizontal bottom edge (y0 == y1) fills its bottom row",
          "[03_interpolate_fill][step6][fill][flat]") {
  const PixelSet expected{
      {0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0},  // the flat bottom, 0..4
      {1, 1}, {2, 1}, {3, 1},                  // 1..3
      {2, 2},                                  // the apex
  };
  for (const PixelSet& pixels : pixels_in_every_order({{{0, 0}, {4, 0}, {2, 2}}})) {
    CHECK(pixels == expected);
  }
}

TEST_CASE("A horizontal top edge (y1 == y2) fills its top row",
          "[03_interpolate_fill][step6][fill][flat]") {
  const PixelSet expected{
      {2, 0},                                  // the apex
      {1, 1}, {2, 1}, {3, 1},                  // 1..3
      {0, 2}, {1, 2}, {2, 2}, {3, 2}, {4, 2},  // the flat top, 0..4
  };
  for (const PixelSet& pixels : pixels_in_every_order({{{2, 0}, {0, 2}, {4, 2}}})) {
    CHECK(pixels == expected);
  }
}

TEST_CASE("A triangle two rows tall keeps both rows in every order",
          "[03_interpolate_fill][step6][fill][flat]") {
  const PixelSet expected{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}, {2, 1}};
  for (const PixelSet& pixels : pixels_in_every_order({{{0, 0}, {4, 0}, {2, 1}}})) {
    CHECK(pixels == expected);
  }
}

TEST_CASE("All three vertices on one row fill one span from the leftmost to the rightmost",
          "[03_interpolate_fill][step6][fill][degenerate]") {
  const PixelSet expected{{1, 3}, {2, 3}, {3, 3}, {4, 3}, {5, 3}, {6, 3}, {7, 3}, {8, 3}};
  for (const PixelSet& pixels : pixels_in_every_order({{{5, 3}, {1, 3}, {8, 3}}})) {
    CHECK(pixels == expected);
  }
}

TEST_CASE("Each of the six vertex orders gives the same pixels",
          "[03_interpolate_fill][step6][fill][order]") {
  // Measured: 0 pixels differ. Coordinates in 0..11 make many flat edges and exact ties.
  tri::testing::Random random(313);
  int differing = 0;
  for (int i = 0; i < 2000; ++i) {
    const auto pixels = pixels_in_every_order(random_vertices(random, 0, 11), 12, 12);
    for (const PixelSet& other : pixels) differing += differing_pixels(pixels[0], other);
  }
  CHECK(differing == 0);
}

TEST_CASE("Each pixel is written at most once", "[03_interpolate_fill][step6][fill]") {
  tri::testing::Random random(314);
  for (int i = 0; i < 500; ++i) {
    const Vertices v = random_vertices(random, -10, side + 10);
    Canvas canvas(side, side);
    canvas.enable_write_counts();
    draw_filled_triangle(canvas, v[0], v[1], v[2], tri::colors::white);
    CHECK(tri::testing::overdrawn_pixels(canvas).empty());
    CHECK(canvas.outside_writes() == 0);
  }
}

TEST_CASE("Clipping the rows before step 2 moves only exact halfway ties",
          "[03_interpolate_fill][step6][fill][clip]") {
  // Triangles reaching up to 40 pixels past a 32x32 canvas, drawn with and without clipping the
  // rows first. A clipped edge starts from its x evaluated directly at the first visible row,
  // which is exact; the book's running sum may land a hair either side of a halfway x.
  // Measured: 64 pixels differ over 2000 triangles, every one of them at such a tie.
  tri::testing::Random random(315);
  int differing = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vertices v = random_vertices(random, -40, side + 40);
    const PixelSet clipped = fill_pixels(v, side, side), book = book_fill_pixels(v, side, side);
    for (const auto& [x, y] : minus(clipped, book)) CHECK(on_halfway_tie(v, x, y));
    for (const auto& [x, y] : minus(book, clipped)) CHECK(on_halfway_tie(v, x, y));
    differing += differing_pixels(clipped, book);
  }
  CHECK(differing == 64);
}
