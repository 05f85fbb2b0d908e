/// @file
/// What chapter 04's tests share: the article's triangles, drawing one step into a counting canvas
/// and reading back its pixels, whole rows of pixels, and the seeded triangles of the order tests.
#pragma once

#include <initializer_list>
#include <vector>

#include <glm/vec2.hpp>

#include "chapters/02_wireframe/example_triangles.hpp"
#include "common/canvas.hpp"
#include "tests/support/pixels.hpp"

namespace tri::ch04::testing {

using tri::testing::minus;
using tri::testing::PixelSet;
using tri::testing::vertex_orders;
using tri::testing::VertexTriple;

using ch02::tinyrenderer_triangles;
/// tinyrenderer's red triangle, (10, 70), (50, 160), (70, 80).
inline constexpr const auto& red_triangle = tinyrenderer_triangles[0].vertices;

/// The signature of the chapter's fill steps.
using FillStep = void (*)(Canvas&, glm::ivec2, glm::ivec2, glm::ivec2, Color);

/// A canvas that counts writes, with the step drawn on it in white.
inline Canvas drawn_by(FillStep step, glm::ivec2 a, glm::ivec2 b, glm::ivec2 c, int width = 200,
                       int height = 200) {
  Canvas canvas(width, height);
  canvas.enable_write_counts();
  step(canvas, a, b, c, colors::white);
  return canvas;
}

/// The pixels a fill step writes.
inline PixelSet pixels_of(FillStep step, glm::ivec2 a, glm::ivec2 b, glm::ivec2 c, int width = 200,
                          int height = 200) {
  return tri::testing::written_pixels(drawn_by(step, a, b, c, width, height));
}

/// Every pixel of row y from x_first to x_last, both included.
inline void add_row(PixelSet& set, int y, int x_first, int x_last) {
  for (int x = x_first; x <= x_last; ++x) set.emplace(x, y);
}

/// A row of pixels: row y from column x_first to column x_last, both included.
struct Row {
  int y, x_first, x_last;
};

/// The pixels of the given rows, e.g. {{0, 0, 0}, {1, 0, 3}} for (0,0) and (0,1) to (3,1).
inline PixelSet pixels_in_rows(std::initializer_list<Row> rows) {
  PixelSet set;
  for (const Row& row : rows) add_row(set, row.y, row.x_first, row.x_last);
  return set;
}

/// The 300 seeded triangles (seed 4) on a 32x32 canvas that the vertex-order tests share.
inline std::vector<VertexTriple> order_test_triangles() {
  tri::testing::Random random(4);
  std::vector<VertexTriple> triangles;
  for (int n = 0; n < 300; ++n) triangles.push_back(tri::testing::random_vertices(random, 0, 31));
  return triangles;
}

}  // namespace tri::ch04::testing
