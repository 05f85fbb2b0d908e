#include <algorithm>
#include <array>

#include <catch2/catch.hpp>

#include "chapters/02_wireframe/example_triangles.hpp"
#include "chapters/06_barycentric/examples.hpp"
#include "chapters/06_barycentric/fill.hpp"
#include "chapters/06_barycentric/random_triangles.hpp"
#include "tests/support/pixels.hpp"

using namespace tri::ch06;
using namespace testing;
using namespace tri::testing;
using tri::Canvas;

namespace {

PixelSet unguarded_pixels(const PixelTriangle& t, int width, int height) {
  return pixels_drawn(width, height, [&](Canvas& canvas) {
    fill_triangle_barycentric_unguarded<double>(canvas, t[0], t[1], t[2], tri::colors::white);
  });
}

}  // namespace

TEST_CASE("The hand-checked triangle fills exactly its 13 pixels",
          "[06_barycentric][step4][06][fill]") {
  // Rows from the three edge inequalities x <= 5y - 4, x + y <= 8 and 2x >= y + 1.
  const PixelSet expected{{1, 1},                                  // y = 1
                          {2, 2}, {3, 2}, {4, 2}, {5, 2}, {6, 2},  // y = 2
                          {2, 3}, {3, 3}, {4, 3}, {5, 3},          // y = 3
                          {3, 4}, {4, 4},                          // y = 4
                          {3, 5}};                                 // y = 5
  CHECK(filled_pixels<double>(hand_checked_triangle, 8, 8) == expected);
  CHECK(filled_pixels<float>(hand_checked_triangle, 8, 8) == expected);
}

TEST_CASE("Every vertex order fills the same pixels", "[06_barycentric][step4][06][fill]") {
  Random random(603);
  std::vector<PixelTriangle> triangles{hand_checked_triangle};
  for (const auto& t : tri::ch02::tinyrenderer_triangles) triangles.push_back(t.vertices);
  for (int i = 0; i < 50; ++i) triangles.push_back(random_vertices(random, -20, 84));
  for (const PixelTriangle& t : triangles) {
    const PixelSet first = filled_pixels<double>(t, 64, 64);
    for (const PixelTriangle& order : vertex_orders(t)) {
      CHECK(filled_pixels<double>(order, 64, 64) == first);
      CHECK(filled_pixels<float>(order, 64, 64) == first);
    }
  }
}

TEST_CASE("No pixel is written twice and none outside the canvas",
          "[06_barycentric][step4][06][fill]") {
  Random random(604);
  for (int i = 0; i < 100; ++i) {
    const Canvas canvas = filled<float>(random_vertices(random, -40, 104), 64, 64);
    CHECK(overdrawn_pixels(canvas).empty());
    CHECK(canvas.outside_writes() == 0);
  }
}

TEST_CASE("tinyrenderer's three triangles cover exactly their inclusive pixels",
          "[06_barycentric][step4][06][fill]") {
  const std::array<std::size_t, 3> counts{2521, 4652, 666};
  for (std::size_t i = 0; i < 3; ++i) {
    const auto [a, b, c] = tri::ch02::tinyrenderer_triangles[i].vertices;
    const PixelSet expected = inclusive_pixels(a, b, c, 200, 200);
    CHECK(expected.size() == counts[i]);
    CHECK(filled_pixels<double>({a, b, c}, 200, 200) == expected);
    CHECK(filled_pixels<float>({a, b, c}, 200, 200) == expected);
  }
}

TEST_CASE("Zero-area triangles draw nothing", "[06_barycentric][step3][06][fill][degenerate]") {
  const std::array<PixelTriangle, 6> degenerate{{
      {{{0, 0}, {0, 0}, {0, 0}}},  // tri 0 0 0 0 0 0
      {{{3, 4}, {3, 4}, {3, 4}}},  // all three equal, inside the canvas
      {{{2, 2}, {2, 2}, {9, 6}}},  // two equal
      {{{1, 2}, {9, 2}, {5, 2}}},  // horizontal
      {{{4, 0}, {4, 9}, {4, 3}}},  // vertical
      {{{1, 1}, {3, 2}, {9, 5}}},  // diagonal
  }};
  for (const PixelTriangle& t : degenerate) {
    for (const PixelTriangle& order : vertex_orders(t)) {
      const Canvas canvas = filled<double>(order, 12, 12);
      CHECK(written_pixels(canvas).empty());
      CHECK(written_pixels(filled<float>(order, 12, 12)).empty());
      CHECK(canvas.outside_writes() == 0);
    }
  }
}

TEST_CASE("Without the guard a zero-area triangle draws the pixel centres on its segment",
          "[06_barycentric][step3][06][fill][degenerate]") {
  // Each of these pixels has the weights (NaN, NaN, NaN), which the inside test lets through.
  CHECK(unguarded_pixels({{{0, 0}, {0, 0}, {0, 0}}}, 12, 12) == PixelSet{{0, 0}});
  CHECK(unguarded_pixels({{{1, 1}, {3, 2}, {9, 5}}}, 12, 12) ==
        PixelSet{{1, 1}, {3, 2}, {5, 3}, {7, 4}, {9, 5}});
  CHECK(unguarded_pixels({{{1, 2}, {9, 2}, {5, 2}}}, 12, 12) ==
        PixelSet{{1, 2}, {2, 2}, {3, 2}, {4, 2}, {5, 2}, {6, 2}, {7, 2}, {8, 2}, {9, 2}});
  // (2,2)-(9,6) passes through no other pixel centre: only the two ends.
  CHECK(unguarded_pixels({{{2, 2}, {2, 2}, {9, 6}}}, 12, 12) == PixelSet{{2, 2}, {9, 6}});
}

TEST_CASE("With the guard removed a triangle of non-zero area fills the same pixels",
          "[06_barycentric][step4][06][fill]") {
  Random random(605);
  for (int i = 0; i < 50; ++i) {
    const auto [a, b, c] = random_vertices(random, -10, 40);
    if (inclusive_pixels(a, b, c, 32, 32).empty()) continue;
    CHECK(unguarded_pixels({a, b, c}, 32, 32) == filled_pixels<double>({a, b, c}, 32, 32));
  }
}

TEST_CASE("Colouring by the weights shows each vertex's own colour at its pixel",
          "[06_barycentric][step5][06][fill][weights]") {
  const auto [a, b, c] = hand_checked_triangle;
  Canvas canvas(8, 8);
  canvas.enable_write_counts();
  fill_triangle_with_weights(canvas, a, b, c, tri::colors::red, tri::colors::green,
                             tri::colors::blue);
  CHECK(canvas.pixel(a.x, a.y) == tri::colors::red);
  CHECK(canvas.pixel(b.x, b.y) == tri::colors::green);
  CHECK(canvas.pixel(c.x, c.y) == tri::colors::blue);
  // (3, 3) has the weights (1/3, 2/9, 4/9): 85, 57 and 113 out of 255.
  CHECK(canvas.pixel(3, 3) == tri::Color{85, 57, 113, 255});
  CHECK(written_pixels(canvas) == filled_pixels<double>({a, b, c}, 8, 8));
}
