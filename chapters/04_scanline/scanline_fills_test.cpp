#include "chapters/04_scanline/scanline_fills.hpp"

#include <catch2/catch.hpp>

#include "chapters/04_scanline/scanline_test_support.hpp"

namespace {

using namespace tri::ch04;
using namespace tri::ch04::testing;
using namespace tri::testing;
using tri::Canvas;

// The rows a pixel set touches.
std::set<int> rows_of(const PixelSet& pixels) {
  std::set<int> rows;
  for (const auto& p : pixels) rows.insert(p.second);
  return rows;
}

bool has_tied_y(glm::ivec2 a, glm::ivec2 b, glm::ivec2 c) {
  return a.y == b.y || b.y == c.y || a.y == c.y;
}

}  // namespace

TEST_CASE("Step 6 fills a small hand-checked triangle row by row", "[04_scanline][step6]") {
  // t0 = (0,0), t1 = (6,2), t2 = (2,5). A: x = 2i/5. B: 6i/2 for i <= 2, then 6 - 4(i-2)/3.
  // Each truncated toward its start vertex: rows 0..5 span [0,0] [0,3] [0,6] [1,5] [1,4] [2,2].
  const PixelSet expected =
      pixels_in_rows({{0, 0, 0}, {1, 0, 3}, {2, 0, 6}, {3, 1, 5}, {4, 1, 4}, {5, 2, 2}});
  const PixelSet filled = pixels_of(fill_single_loop, {0, 0}, {6, 2}, {2, 5}, 8, 6);
  CHECK(filled == expected);
  // The centres inside or on the triangle span [0,0] [1,3] [1,6] [2,4] [2,3] [2,2]: the int
  // casts add six pixels outside it and lose none.
  const PixelSet inside = inclusive_pixels({0, 0}, {6, 2}, {2, 5}, 8, 6);
  CHECK(minus(inside, filled).empty());
  CHECK(minus(filled, inside) == PixelSet{{0, 1}, {0, 2}, {1, 3}, {5, 3}, {1, 4}, {4, 4}});
}

TEST_CASE("Step 5 fills the same triangle with bent B boundaries and row t1.y twice",
          "[04_scanline][step5]") {
  // Lower loop B = 6i/3 (the +1 height): [0,0] [0,2] [0,4]; upper loop B = 6 - 4i/4: rows 2..5
  // [0,6] [1,5] [1,4] [2,3].
  const PixelSet expected =
      pixels_in_rows({{0, 0, 0}, {1, 0, 2}, {2, 0, 6}, {3, 1, 5}, {4, 1, 4}, {5, 2, 3}});
  const Canvas canvas = drawn_by(fill_two_loops, {0, 0}, {6, 2}, {2, 5}, 8, 6);
  const PixelSet filled = written_pixels(canvas);
  CHECK(filled == expected);
  CHECK(overdrawn_pixels(canvas) == PixelSet{{0, 2}, {1, 2}, {2, 2}, {3, 2}, {4, 2}});
  // Against the single loop: loses (3,1), which lies on the edge t0-t1, and adds (3,5) beside t2.
  const PixelSet single = pixels_of(fill_single_loop, {0, 0}, {6, 2}, {2, 5}, 8, 6);
  CHECK(minus(single, filled) == PixelSet{{3, 1}});
  CHECK(minus(filled, single) == PixelSet{{3, 5}});
}

TEST_CASE("The int cast puts (10,72) into the red triangle though its centre lies outside",
          "[04_scanline][traps][int-cast][trap]") {
  // Row 72 of the red triangle: boundary A is at x = 10 + 40 * 2/90 = 10.89. Truncation starts
  // the span at 10; rounding would start it at 11, the first centre inside.
  const PixelSet filled =
      pixels_of(fill_single_loop, red_triangle[0], red_triangle[1], red_triangle[2]);
  const PixelSet inside =
      inclusive_pixels(red_triangle[0], red_triangle[1], red_triangle[2], 200, 200);
  CHECK(filled.count({10, 72}) == 1);
  CHECK(inside.count({10, 72}) == 0);
  CHECK(inside.count({11, 72}) == 1);
  const auto t = sort_by_y(red_triangle[0], red_triangle[1], red_triangle[2]);
  CHECK(single_loop_ends(t, 2).a == 10);
}

TEST_CASE("The two-loop fill draws row t1.y twice", "[04_scanline][step5]") {
  const std::size_t expected_overdraw[] = {51, 51, 39};
  for (int i = 0; i < 3; ++i) {
    const auto [a, b, c] = tinyrenderer_triangles[i].vertices;
    const PixelSet twice = overdrawn_pixels(drawn_by(fill_two_loops, a, b, c));
    CHECK(twice.size() == expected_overdraw[i]);
    CHECK(rows_of(twice) == std::set<int>{sort_by_y(a, b, c).p1.y});
  }
}

TEST_CASE("The published single loop stops one row short and never draws row t2.y",
          "[04_scanline][traps][step6][trap]") {
  int missing_rows = 0;
  std::size_t missing_pixels = 0;
  for (const auto& triangle : tinyrenderer_triangles) {
    const auto [a, b, c] = triangle.vertices;
    const PixelSet fixed = pixels_of(fill_single_loop, a, b, c);
    const PixelSet published = pixels_of(fill_single_loop_as_published, a, b, c);
    const PixelSet lost = minus(fixed, published);
    CHECK(minus(published, fixed).empty());
    const glm::ivec2 top = sort_by_y(a, b, c).p2;
    CHECK(lost == PixelSet{{top.x, top.y}});  // a pointed top: just the vertex
    missing_rows += static_cast<int>(rows_of(lost).size());
    missing_pixels += lost.size();
  }
  CHECK(missing_rows == 3);
  CHECK(missing_pixels == 3);
  // A flat top loses its whole top edge: (0,3) .. (4,3).
  const PixelSet lost = minus(pixels_of(fill_single_loop, {2, 0}, {0, 3}, {4, 3}),
                              pixels_of(fill_single_loop_as_published, {2, 0}, {0, 3}, {4, 3}));
  CHECK(lost == pixels_in_rows({{3, 0, 4}}));
}

TEST_CASE("The single loop takes the second half from the first row when t0.y == t1.y",
          "[04_scanline][traps][step6][division-by-zero]") {
  // Without `|| t1.y == t0.y`, row 0 would divide 0 by a lower height of 0.
  const auto t = sort_by_y({0, 0}, {4, 0}, {2, 3});
  const auto first_row = single_loop_ends(t, 0);
  CHECK(first_row.a == 0);
  CHECK(first_row.b == 4);
  const PixelSet expected = pixels_in_rows({{0, 0, 4}, {1, 0, 4}, {2, 1, 3}, {3, 2, 2}});
  for (const auto& order : vertex_orders({0, 0}, {4, 0}, {2, 3})) {
    CHECK(pixels_of(fill_single_loop, order[0], order[1], order[2]) == expected);
  }
}

TEST_CASE("The single loop stays in the first half to the top when t1.y == t2.y",
          "[04_scanline][step6][division-by-zero]") {
  const PixelSet expected = pixels_in_rows({{0, 2, 2}, {1, 2, 2}, {2, 1, 3}, {3, 0, 4}});
  for (const auto& order : vertex_orders({2, 0}, {0, 3}, {4, 3})) {
    CHECK(pixels_of(fill_single_loop, order[0], order[1], order[2]) == expected);
  }
  CHECK(expected == inclusive_pixels({2, 0}, {0, 3}, {4, 3}, 200, 200));
}

TEST_CASE("The two-loop fill on a flat bottom depends on which bottom vertex is t0",
          "[04_scanline][step5][division-by-zero][order]") {
  // The second loop runs A over the exact height from t0 and B over height + 1 from t1.
  const PixelSet left_first = pixels_in_rows({{0, 0, 4}, {1, 0, 4}, {2, 1, 3}, {3, 2, 3}});
  const PixelSet right_first = pixels_in_rows({{0, 0, 4}, {1, 0, 4}, {2, 1, 3}, {3, 1, 2}});
  CHECK(pixels_of(fill_two_loops, {0, 0}, {4, 0}, {2, 3}) == left_first);
  CHECK(pixels_of(fill_two_loops, {4, 0}, {0, 0}, {2, 3}) == right_first);
}

TEST_CASE("The two-loop fill on a flat top covers the top edge with its second loop",
          "[04_scanline][step5][division-by-zero]") {
  const PixelSet single = pixels_of(fill_single_loop, {2, 0}, {0, 3}, {4, 3});
  for (const auto& order : vertex_orders({2, 0}, {0, 3}, {4, 3})) {
    const Canvas canvas = drawn_by(fill_two_loops, order[0], order[1], order[2]);
    CHECK(written_pixels(canvas) == single);
    CHECK(rows_of(overdrawn_pixels(canvas)) == std::set<int>{3});
    CHECK(overdrawn_pixels(canvas).size() == 4);  // the lower loop's [1,4] or [0,3]
  }
}

TEST_CASE("Fill steps 5 and 6 draw nothing when all three vertices share a row",
          "[04_scanline][traps][step5][step6][division-by-zero]") {
  for (const auto fill : {fill_two_loops, fill_single_loop, fill_single_loop_as_published}) {
    CHECK(pixels_of(fill, {0, 2}, {5, 2}, {3, 2}).empty());
    CHECK(pixels_of(fill, {0, 0}, {0, 0}, {0, 0}).empty());
  }
}

TEST_CASE("Collinear vertices on a slant fill a staircase, though the triangle has no area",
          "[04_scanline][step5][step6]") {
  CHECK(pixels_of(fill_single_loop, {0, 0}, {2, 2}, {4, 4}) ==
        PixelSet{{0, 0}, {1, 1}, {2, 2}, {3, 3}, {4, 4}});
  CHECK(pixels_of(fill_two_loops, {0, 0}, {2, 2}, {4, 4}) ==
        PixelSet{{0, 0}, {0, 1}, {1, 1}, {1, 2}, {2, 2}, {2, 3}, {3, 3}, {3, 4}, {4, 4}});
}

TEST_CASE("The two fills part ways on the article's triangles by these pixels",
          "[04_scanline][step6][step5]") {
  // {pixels only the two loops draw, pixels only the single loop draws}, per triangle.
  const std::pair<std::size_t, std::size_t> expected[] = {{20, 29}, {60, 10}, {10, 29}};
  for (int i = 0; i < 3; ++i) {
    const auto [a, b, c] = tinyrenderer_triangles[i].vertices;
    const auto t = sort_by_y(a, b, c);
    const PixelSet two = pixels_of(fill_two_loops, a, b, c);
    const PixelSet one = pixels_of(fill_single_loop, a, b, c);
    const PixelSet only_two = minus(two, one), only_one = minus(one, two);
    CHECK(std::pair(only_two.size(), only_one.size()) == expected[i]);
    // The bent B of the lower loop loses pixels below t1; the bent B of the upper loop adds
    // pixels above it.
    for (const int y : rows_of(only_one)) CHECK((y > t.p0.y && y < t.p1.y));
    for (const int y : rows_of(only_two)) CHECK((y > t.p1.y && y <= t.p2.y));
  }
}

TEST_CASE("The single loop draws each pixel once and the same pixels for all six vertex orders",
          "[04_scanline][step6][order]") {
  int tied = 0;
  for (const auto& [a, b, c] : order_test_triangles()) {
    if (has_tied_y(a, b, c)) ++tied;
    const Canvas canvas = drawn_by(fill_single_loop, a, b, c, 32, 32);
    CHECK(overdrawn_pixels(canvas).empty());  // one pass per row, each row once
    const PixelSet expected = written_pixels(canvas);
    for (const auto& order : vertex_orders(a, b, c)) {
      CHECK(pixels_of(fill_single_loop, order[0], order[1], order[2], 32, 32) == expected);
    }
  }
  CHECK(tied == 19);  // the ties are the cases where the sort's result depends on order
}

TEST_CASE("The two-loop fill depends on vertex order only when two vertices share a row",
          "[04_scanline][step5][order]") {
  int order_dependent = 0;
  for (const auto& [a, b, c] : order_test_triangles()) {
    const PixelSet first = pixels_of(fill_two_loops, a, b, c, 32, 32);
    bool differs = false;
    for (const auto& order : vertex_orders(a, b, c)) {
      differs |= pixels_of(fill_two_loops, order[0], order[1], order[2], 32, 32) != first;
    }
    if (differs) {
      ++order_dependent;
      CHECK(has_tied_y(a, b, c));
    }
  }
  CHECK(order_dependent == 18);  // of the 19 triangles with a tie
}

TEST_CASE("Fill steps stay on the canvas and write each pixel at most twice for huge vertices",
          "[04_scanline][traps][safety]") {
  for (const int far : {10'000'000, 1 << 30}) {
    const std::array<std::array<glm::ivec2, 3>, 4> cases{{
        {{{-far, -far}, {far, -far}, {0, far}}},         // covers the whole canvas
        {{{-far, 10}, {far, 20}, {5, far}}},             // t1 above part of the canvas rows
        {{{-far, -far}, {0, 0}, {far, far}}},            // collinear through the canvas
        {{{far, far}, {far, far - 1}, {far - 1, far}}},  // tiny and far away
    }};
    for (const auto fill : {tri::ch04::fill_lower_half, fill_two_loops, fill_single_loop,
                            fill_single_loop_as_published}) {
      for (const auto& v : cases) {
        const Canvas canvas = drawn_by(fill, v[0], v[1], v[2], 64, 64);
        CHECK(canvas.outside_writes() == 0);
        for (const auto count : canvas.write_counts()) CHECK(count <= 2);
      }
    }
    for (const auto fill : {fill_two_loops, fill_single_loop, fill_single_loop_as_published}) {
      const Canvas whole = drawn_by(fill, {-far, -far}, {far, -far}, {0, far}, 64, 64);
      for (const auto count : whole.write_counts()) CHECK(count == 1);
    }
  }
}
