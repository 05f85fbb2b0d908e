#include "chapters/04_scanline/outline_steps.hpp"

#include <catch2/catch.hpp>

#include "chapters/01_lines/lines.hpp"
#include "chapters/04_scanline/boundaries.hpp"
#include "chapters/04_scanline/scanline_test_support.hpp"
#include "common/pixel_diagram.hpp"

namespace {

using tri::Canvas;
using tri::ch04::testing::red_triangle;
using tri::ch04::testing::tinyrenderer_triangles;
using tri::diagram_colors::blue;
using tri::diagram_colors::vermillion;
using tri::testing::PixelSet;
using tri::testing::written_pixels;

// The pixels of chapter 01's Bresenham line from p to q.
PixelSet line_pixels(glm::ivec2 p, glm::ivec2 q) {
  Canvas canvas(200, 200);
  canvas.enable_write_counts();
  tri::ch01::draw_line_bresenham(canvas, p, q, tri::colors::white);
  return written_pixels(canvas);
}

// The pixels of a canvas that hold one colour.
PixelSet pixels_coloured(const Canvas& canvas, tri::Color color) {
  PixelSet set;
  for (int y = 0; y < canvas.height(); ++y) {
    for (int x = 0; x < canvas.width(); ++x) {
      if (canvas.pixel(x, y) == color) set.emplace(x, y);
    }
  }
  return set;
}

PixelSet outline_pixels(glm::ivec2 a, glm::ivec2 b, glm::ivec2 c) {
  Canvas canvas(200, 200);
  canvas.enable_write_counts();
  tri::ch04::draw_outline(canvas, a, b, c, tri::colors::white);
  return written_pixels(canvas);
}

}  // namespace

TEST_CASE("Step 1 draws the three edges of a small triangle and nothing inside",
          "[04_scanline][step1]") {
  // Legs along the axes, hypotenuse one pixel per row from (4,0) to (0,4).
  const PixelSet expected{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}, {0, 1},
                          {0, 2}, {0, 3}, {0, 4}, {3, 1}, {2, 2}, {1, 3}};
  CHECK(outline_pixels({0, 0}, {4, 0}, {0, 4}) == expected);
}

TEST_CASE("Step 1 draws the same pixels for all six vertex orders", "[04_scanline][step1][order]") {
  for (const auto& triangle : tinyrenderer_triangles) {
    const auto [a, b, c] = triangle.vertices;
    const PixelSet expected = outline_pixels(a, b, c);
    PixelSet edges = line_pixels(a, b);
    edges.merge(line_pixels(b, c));
    edges.merge(line_pixels(c, a));
    CHECK(expected == edges);
    for (const auto& order : tri::testing::vertex_orders(a, b, c)) {
      CHECK(outline_pixels(order[0], order[1], order[2]) == expected);
    }
  }
}

TEST_CASE("Step 2 draws boundary A from t0 to t2 in vermillion over boundary B in blue",
          "[04_scanline][step2]") {
  for (const auto& triangle : tinyrenderer_triangles) {
    const auto [a, b, c] = triangle.vertices;
    Canvas canvas(200, 200);
    tri::ch04::draw_sorted_boundaries(canvas, a, b, c);
    const auto t = tri::ch04::sort_by_y(a, b, c);
    const PixelSet boundary_a = line_pixels(t.p0, t.p2);
    PixelSet boundary_b = line_pixels(t.p0, t.p1);
    boundary_b.merge(line_pixels(t.p1, t.p2));
    CHECK(pixels_coloured(canvas, vermillion) == boundary_a);
    CHECK(pixels_coloured(canvas, blue) == tri::testing::minus(boundary_b, boundary_a));
  }
  // The red triangle: A is the long edge on the left, rising from (10,70) to (50,160).
  Canvas canvas(200, 200);
  tri::ch04::draw_sorted_boundaries(canvas, red_triangle[0], red_triangle[1], red_triangle[2]);
  CHECK(canvas.pixel(10, 70) == vermillion);
  CHECK(canvas.pixel(50, 160) == vermillion);
  CHECK(canvas.pixel(70, 80) == blue);
}

TEST_CASE("Steps 1 and 2 draw a triangle lying on one row as a segment",
          "[04_scanline][step1][step2]") {
  PixelSet segment;
  tri::ch04::testing::add_row(segment, 2, 0, 5);
  CHECK(outline_pixels({0, 2}, {5, 2}, {3, 2}) == segment);
  // Equal y: nothing swaps, so t0 = (0,2), t1 = (5,2), t2 = (3,2) and A covers x = 0..3.
  Canvas canvas(200, 200);
  tri::ch04::draw_sorted_boundaries(canvas, {0, 2}, {5, 2}, {3, 2});
  CHECK(pixels_coloured(canvas, vermillion) == PixelSet{{0, 2}, {1, 2}, {2, 2}, {3, 2}});
  CHECK(pixels_coloured(canvas, blue) == PixelSet{{4, 2}, {5, 2}});
}

TEST_CASE("Outline steps far off the canvas stay bounded and write nothing outside it",
          "[04_scanline][traps][safety]") {
  // Chapter 01's Bresenham walks only the canvas columns (or rows) of the major axis and skips
  // the steps whose minor coordinate is off the canvas.
  constexpr int far = 10'000'000;
  Canvas canvas(64, 64);
  canvas.enable_write_counts();
  tri::ch04::draw_outline(canvas, {-far, -far}, {far, -far}, {0, far}, tri::colors::white);
  tri::ch04::draw_sorted_boundaries(canvas, {-far, -far}, {far, -far}, {0, far});
  CHECK(written_pixels(canvas).empty());
  CHECK(canvas.outside_writes() == 0);
  canvas.clear(tri::colors::black);
  tri::ch04::draw_outline(canvas, {0, 0}, {0, 0}, {0, 0}, tri::colors::white);
  CHECK(written_pixels(canvas) == PixelSet{{0, 0}});
  CHECK(canvas.outside_writes() == 0);
}
