// Figure 7-3: the fill with chapter 02's outline on top. The fill computes x = f(y) on every
// edge; the outline computes y = f(x) on edges wider than tall, and the two round differently.
#include <cstdlib>

#include <catch2/catch.hpp>

#include "chapters/01_lines/lines.hpp"
#include "chapters/02_wireframe/wireframe.hpp"
#include "chapters/03_interpolate_fill/test_helpers.hpp"
#include "common/centered_view.hpp"

using namespace tri::ch03;
using namespace tri::ch03::testing;
using tri::Canvas;

namespace {

PixelSet outline_pixels(const Vertices& v, int width, int height) {
  Canvas canvas(width, height);
  canvas.enable_write_counts();
  tri::ch02::draw_wireframe_triangle(canvas, v[0], v[1], v[2], tri::colors::black);
  return tri::testing::written_pixels(canvas);
}

PixelSet line_pixels(glm::ivec2 a, glm::ivec2 b, int width, int height) {
  Canvas canvas(width, height);
  canvas.enable_write_counts();
  tri::ch01::draw_line_gambetta(canvas, a, b, tri::colors::black);
  return tri::testing::written_pixels(canvas);
}

// draw_line_gambetta computes y = f(x) exactly when the edge is wider than tall.
bool drawn_as_y_of_x(glm::ivec2 a, glm::ivec2 b) {
  return std::abs(b.x - a.x) > std::abs(b.y - a.y);
}

}  // namespace

PixelSet outline_outside_fill(const Vertices& v, int width, int height) {
  return minus(outline_pixels(v, width, height), fill_pixels(v, width, height));
}

TEST_CASE("Figure 7-3: the outline stays in the fill, but not upside down", "[outline][figure]") {
  Canvas canvas(600, 600);
  tri::CenteredView view(canvas);
  const Vertices v{view.to_canvas({-200, -250}), view.to_canvas({200, 50}),
                   view.to_canvas({20, 250})};
  // Measured: 0 of the outline's 1100 pixels leave the fill. P0-P1 (400 wide, 300 tall) is the
  // only edge drawn as y = f(x); the fill's x there is a whole number or a third off it, and
  // each outline pixel that could stick out is an exact halfway tie that rounds up, inwards.
  CHECK(outline_outside_fill(v, 600, 600).empty());
  // Flipped top to bottom, the same ties round up and out: measured 100 pixels, all on that
  // edge.
  const Vertices flipped{view.to_canvas({-200, 250}), view.to_canvas({200, -50}),
                         view.to_canvas({20, -250})};
  const PixelSet outside = outline_outside_fill(flipped, 600, 600);
  CHECK(outside.size() == 100);
  CHECK(minus(outside, line_pixels(flipped[0], flipped[1], 600, 600)).empty());
}

TEST_CASE("tinyrenderer's triangles: the outline leaves the fill on edges wider than tall",
          "[outline][figure]") {
  // Measured: 20, 0 and 30 outline pixels outside the fill.
  CHECK(outline_outside_fill({{{10, 70}, {50, 160}, {70, 80}}}, 200, 200).size() == 20);
  CHECK(outline_outside_fill({{{180, 50}, {150, 1}, {70, 180}}}, 200, 200).empty());
  CHECK(outline_outside_fill({{{180, 150}, {120, 160}, {130, 180}}}, 200, 200).size() == 30);
}

TEST_CASE("Outline pixels of edges drawn as x = f(y) always lie in the fill", "[outline]") {
  tri::testing::Random random(321);
  for (int i = 0; i < 1000; ++i) {
    const Vertices v = random_vertices(random, 0, 39);
    const PixelSet fill = fill_pixels(v, 40, 40);
    PixelSet y_of_x_edges;
    for (int e = 0; e < 3; ++e) {
      const glm::ivec2 a = v[e], b = v[(e + 1) % 3];
      const PixelSet line = line_pixels(a, b, 40, 40);
      if (drawn_as_y_of_x(a, b)) {
        y_of_x_edges.insert(line.begin(), line.end());
      } else {
        CHECK(minus(line, fill).empty());  // the same interpolate, rounded the same way
      }
    }
    CHECK(minus(minus(outline_pixels(v, 40, 40), fill), y_of_x_edges).empty());
  }
}
