// Chapter 02's tests: the outline is the three lines, closed, and blind to the vertex order.
#include <algorithm>
#include <array>
#include <iterator>
#include <stdexcept>
#include <vector>

#include <catch2/catch.hpp>

#include "chapters/01_lines/lines.hpp"
#include "chapters/02_wireframe/example_triangles.hpp"
#include "chapters/02_wireframe/wireframe.hpp"
#include "common/centered_view.hpp"
#include "tests/support/pixels.hpp"

namespace {

using tri::Canvas;
using tri::testing::PixelSet;
using tri::testing::Random;
using Vertices = std::array<glm::ivec2, 3>;

constexpr int side = 48;

PixelSet outline_pixels(const Vertices& v, int width = side, int height = side) {
  return tri::testing::pixels_drawn(width, height, [&](Canvas& canvas) {
    tri::ch02::draw_wireframe_triangle(canvas, v[0], v[1], v[2], tri::colors::white);
  });
}

PixelSet line_pixels(glm::ivec2 a, glm::ivec2 b) {
  Canvas canvas(side, side);
  canvas.enable_write_counts();
  tri::ch01::draw_line_gambetta(canvas, a, b, tri::colors::white);
  return tri::testing::written_pixels(canvas);
}

Vertices random_vertices(Random& random) {
  return {glm::ivec2{random.integer(0, side - 1), random.integer(0, side - 1)},
          glm::ivec2{random.integer(0, side - 1), random.integer(0, side - 1)},
          glm::ivec2{random.integer(0, side - 1), random.integer(0, side - 1)}};
}

// Flood fill from one pixel through the 8 neighbours; the set is connected if that reaches all.
bool eight_connected(const PixelSet& pixels) {
  if (pixels.empty()) return true;
  PixelSet reached{*pixels.begin()};
  std::vector<std::pair<int, int>> todo{*pixels.begin()};
  while (!todo.empty()) {
    const auto [x, y] = todo.back();
    todo.pop_back();
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const std::pair<int, int> next{x + dx, y + dy};
        if (pixels.count(next) != 0 && reached.insert(next).second) todo.push_back(next);
      }
    }
  }
  return reached.size() == pixels.size();
}

}  // namespace

TEST_CASE("A hand-checked outline is exactly its three lines' pixels",
          "[02_wireframe][step1][wireframe]") {
  // Bottom row, left column and the 45-degree diagonal, which is drawn as x = f(y).
  const PixelSet right_triangle{
      {0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0},  // bottom
      {0, 1}, {0, 2}, {0, 3}, {0, 4},          // left
      {3, 1}, {2, 2}, {1, 3},                  // diagonal
  };
  CHECK(outline_pixels({{{0, 0}, {4, 0}, {0, 4}}}) == right_triangle);
  const PixelSet slanted{
      {1, 1}, {2, 1}, {3, 2}, {4, 2}, {5, 2}, {6, 3}, {7, 3},  // y = 1 + (x - 1) / 3
      {6, 4}, {5, 5}, {4, 5}, {3, 6},                          // y = 6 - 3 (x - 3) / 4
      {3, 5}, {2, 4}, {2, 3}, {1, 2},                          // x = 1 + 2 (y - 1) / 5
  };
  // The middle edge passes y = 4.5 at x = 5, a tie, which rounds up to (5,5).
  CHECK(outline_pixels({{{1, 1}, {7, 3}, {3, 6}}}) == slanted);
}

TEST_CASE("The outline contains the three vertices", "[02_wireframe][step2][wireframe]") {
  Random random(201);
  for (int i = 0; i < 500; ++i) {
    const Vertices v = random_vertices(random);
    const PixelSet outline = outline_pixels(v);
    for (const glm::ivec2 p : v) CHECK(outline.count({p.x, p.y}) == 1);
  }
}

TEST_CASE("The outline is exactly the union of the three lines' pixels",
          "[02_wireframe][step1][wireframe]") {
  Random random(202);
  for (int i = 0; i < 500; ++i) {
    const Vertices v = random_vertices(random);
    PixelSet lines = line_pixels(v[0], v[1]);
    lines.merge(line_pixels(v[1], v[2]));
    lines.merge(line_pixels(v[2], v[0]));
    CHECK(outline_pixels(v) == lines);
  }
}

TEST_CASE("The outline is closed: its pixels are 8-connected", "[02_wireframe][step2][wireframe]") {
  Random random(203);
  for (int i = 0; i < 500; ++i) CHECK(eight_connected(outline_pixels(random_vertices(random))));
}

TEST_CASE("Each vertex is written by both edges that meet there",
          "[02_wireframe][step2][wireframe]") {
  Canvas canvas(side, side);
  canvas.enable_write_counts();
  tri::ch02::draw_wireframe_triangle(canvas, {1, 1}, {7, 3}, {3, 6}, tri::colors::white);
  CHECK(canvas.write_count(1, 1) == 2);
  CHECK(canvas.write_count(7, 3) == 2);
  CHECK(canvas.write_count(3, 6) == 2);
  // Elsewhere this fat triangle's edges do not touch: the vertices are the only overdraw.
  CHECK(tri::testing::overdrawn_pixels(canvas) == PixelSet{{1, 1}, {7, 3}, {3, 6}});
}

TEST_CASE("Every order of the vertices draws the same outline",
          "[02_wireframe][step4][wireframe][order]") {
  // Measured: 0 pixels differ. draw_line_gambetta always walks from the lower end of the
  // axis it steps along, so even the exact halfway ties round the same way in every order.
  Random random(204);
  int differing_pixels = 0;
  for (int i = 0; i < 500; ++i) {
    Vertices v = random_vertices(random);
    std::sort(v.begin(), v.end(),
              [](glm::ivec2 a, glm::ivec2 b) { return a.x != b.x ? a.x < b.x : a.y < b.y; });
    const PixelSet first = outline_pixels(v);
    while (std::next_permutation(v.begin(), v.end(), [](glm::ivec2 a, glm::ivec2 b) {
      return a.x != b.x ? a.x < b.x : a.y < b.y;
    })) {
      PixelSet difference;
      const PixelSet other = outline_pixels(v);
      std::set_symmetric_difference(first.begin(), first.end(), other.begin(), other.end(),
                                    std::inserter(difference, difference.end()));
      differing_pixels += static_cast<int>(difference.size());
    }
  }
  CHECK(differing_pixels == 0);
}

TEST_CASE("A triangle whose vertices coincide is one pixel, written three times",
          "[02_wireframe][step4][wireframe][degenerate]") {
  Canvas canvas(side, side);
  canvas.enable_write_counts();
  tri::ch02::draw_wireframe_triangle(canvas, {5, 5}, {5, 5}, {5, 5}, tri::colors::white);
  CHECK(tri::testing::written_pixels(canvas) == PixelSet{{5, 5}});
  CHECK(canvas.write_count(5, 5) == 3);
  CHECK(canvas.outside_writes() == 0);
}

TEST_CASE("Collinear vertices outline the segment between the outer two",
          "[02_wireframe][step4][wireframe][degenerate]") {
  CHECK(outline_pixels({{{2, 2}, {10, 6}, {6, 4}}}) == line_pixels({2, 2}, {10, 6}));
}

TEST_CASE("Figure 7-1's triangle lands on the centred canvas with its vertices",
          "[02_wireframe][step1][wireframe][figure]") {
  const int size = tri::ch02::figure_7_1_canvas_size;
  Canvas canvas(size, size);
  canvas.enable_write_counts();
  tri::CenteredView view(canvas);
  const auto& centred = tri::ch02::figure_7_1_triangle;
  const Vertices v{view.to_canvas(centred[0]), view.to_canvas(centred[1]),
                   view.to_canvas(centred[2])};
  CHECK(v == Vertices{{{100, 50}, {500, 350}, {320, 550}}});
  tri::ch02::draw_wireframe_triangle(canvas, v[0], v[1], v[2], tri::colors::black);
  const PixelSet outline = tri::testing::written_pixels(canvas);
  CHECK(eight_connected(outline));
  // One pixel per step along each edge's longer axis (401 + 201 + 501), minus the three
  // vertices that two edges share.
  CHECK(outline.size() == 1100);
  CHECK(canvas.outside_writes() == 0);
}

TEST_CASE("tinyrenderer's three test triangles outline as closed curves",
          "[02_wireframe][step3][wireframe][figure]") {
  std::vector<std::size_t> sizes;
  for (const auto& triangle : tri::ch02::tinyrenderer_triangles) {
    const int size = tri::ch02::tinyrenderer_image_size;
    const PixelSet outline = outline_pixels(triangle.vertices, size, size);
    CHECK(eight_connected(outline));
    sizes.push_back(outline.size());
  }
  // Each edge contributes (longer axis + 1) pixels; the three shared vertices are counted once.
  // The first triangle's top (50,160) is so sharp that both edges also draw (50,159) below it.
  CHECK(sizes ==
        std::vector<std::size_t>{91 + 81 + 61 - 3 - 1, 50 + 180 + 131 - 3, 61 + 21 + 51 - 3});
}

TEST_CASE("outline_edge_pixels gives each edge's pixels, and only the joints are in two",
          "[02_wireframe][step1][wireframe][figure]") {
  const auto edges = tri::ch02::outline_edge_pixels({1, 1}, {7, 3}, {3, 6});
  PixelSet all, twice;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const auto& pixels = edges[i];
    const PixelSet set = [&] {
      PixelSet s;
      for (const auto p : pixels) s.insert({p.x, p.y});
      return s;
    }();
    CHECK(set.size() == pixels.size());
    for (const auto& p : set) {
      if (!all.insert(p).second) twice.insert(p);
    }
  }
  CHECK(edges[0].size() == 7);  // (1,1)-(7,3): one pixel per column 1..7
  CHECK(edges[1].size() == 5);  // (7,3)-(3,6): x = 3..7
  CHECK(edges[2].size() == 6);  // (3,6)-(1,1): steep, y = 1..6
  CHECK(twice == PixelSet{{1, 1}, {7, 3}, {3, 6}});
  CHECK(all == outline_pixels({{{1, 1}, {7, 3}, {3, 6}}}));
  CHECK_THROWS_AS(tri::ch02::outline_edge_pixels({-1, 0}, {3, 3}, {0, 3}), std::invalid_argument);
}

TEST_CASE("tinyrenderer's red triangle: both edges at its top also draw (50,159)",
          "[02_wireframe][step1][wireframe][figure]") {
  const auto [a, b, c] = tri::ch02::tinyrenderer_triangles[0].vertices;
  const auto edges = tri::ch02::outline_edge_pixels(a, b, c);
  for (const std::size_t i : {0, 1}) {
    CHECK(std::count(edges[i].begin(), edges[i].end(), glm::ivec2(50, 159)) == 1);
  }
  CHECK(std::count(edges[2].begin(), edges[2].end(), glm::ivec2(50, 159)) == 0);
}
