// Figure 7-3: the fill with chapter 02's outline on top. The fill computes x = f(y) on every
// edge; the outline computes y = f(x) on edges wider than tall, and the two round differently.
#include <cstdlib>

#include <catch2/catch.hpp>

#include "chapters/01_lines/lines.hpp"
#include "chapters/02_wireframe/example_triangles.hpp"
#include "chapters/02_wireframe/wireframe.hpp"
#include "chapters/03_interpolate_fill/test_helpers.hpp"
#include "common/centered_view.hpp"

using namespace tri::ch03;
using namespace tri::ch03::testing;
using tri::Canvas;

namespace {

PixelSet outline_pixels(const Vertices& v, int width, int height) {
  return tri::testing::pixels_drawn(width, height, [&](Canvas& canvas) {
    tri::ch02::draw_wireframe_triangle(canvas, v[0], v[1], v[2], tri::colors::black);
  });
}

PixelSet line_pixels(glm::ivec2 a, glm::ivec2 b, int width, int height) {
  return tri::testing::pixels_drawn(width, height, [&](Canvas& canvas) {
    tri::ch01::draw_line_gambetta(canvas, a, b, tri::colors::black);
  });
}

// draw_line_gambetta computes y = f(x) exactly when the edge is wider than tall.
bool drawn_as_y_of_x(glm::ivec2 a, glm::ivec2 b) {
  return std::abs(b.x - a.x) > std::abs(b.y - a.y);
}

}  // namespace

PixelSet outline_outside_fill(const Vertices& v, int width, int height) {
  return minus(outline_pixels(v, width, height), fill_pixels(v, width, height));
}

TEST_CASE("Figure 7-3: the outline stays in the fill, but not upside down",
          "[03_interpolate_fill][step6][outline][figure]") {
  const int size = tri::ch02::figure_7_1_canvas_size;
  const Canvas canvas(size, size);
  const tri::CenteredView view(canvas);
  const auto& centred = tri::ch02::figure_7_1_triangle;
  const Vertices v{view.to_canvas(centred[0]), view.to_canvas(centred[1]),
                   view.to_canvas(centred[2])};
  // Measured: 0 of the outline's 1100 pixels leave the fill. P0-P1 (400 wide, 300 tall) is the
  // only edge drawn as y = f(x); the fill's x there is a whole number or a third off it, and
  // each outline pixel that could stick out is an exact halfway tie that rounds up, inwards.
  CHECK(outline_outside_fill(v, size, size).empty());
  // Flipped top to bottom, the same ties round up and out: measured 100 pixels, all on that
  // edge.
  const auto upside_down = [&](glm::ivec2 p) { return view.to_canvas({p.x, -p.y}); };
  const Vertices flipped{upside_down(centred[0]), upside_down(centred[1]), upside_down(centred[2])};
  const PixelSet outside = outline_outside_fill(flipped, size, size);
  CHECK(outside.size() == 100);
  CHECK(minus(outside, line_pixels(flipped[0], flipped[1], size, size)).empty());
}

TEST_CASE("tinyrenderer's triangles: the outline leaves the fill on edges wider than tall",
          "[03_interpolate_fill][step6][outline][figure]") {
  // Measured: 20, 0 and 30 outline pixels outside the fill.
  const auto& triangles = tri::ch02::tinyrenderer_triangles;
  const int size = tri::ch02::tinyrenderer_image_size;
  CHECK(outline_outside_fill(triangles[0].vertices, size, size).size() == 20);
  CHECK(outline_outside_fill(triangles[1].vertices, size, size).empty());
  CHECK(outline_outside_fill(triangles[2].vertices, size, size).size() == 30);
}

TEST_CASE("Outline pixels of edges drawn as x = f(y) always lie in the fill",
          "[03_interpolate_fill][step6][outline]") {
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
