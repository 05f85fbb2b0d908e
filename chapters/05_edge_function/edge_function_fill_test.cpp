#include <algorithm>
#include <array>
#include <cstdlib>
#include <iterator>
#include <numeric>

#include <catch2/catch.hpp>

#include "chapters/02_wireframe/example_triangles.hpp"
#include "chapters/05_edge_function/cross_product.hpp"
#include "chapters/05_edge_function/edge_function_fill.hpp"
#include "tests/support/pixels.hpp"

using namespace tri::ch05;
using namespace tri::testing;
using tri::Canvas;

namespace {

constexpr int two_to_30 = 1 << 30;

// What fill draws on a fresh counting canvas; also checks it wrote each pixel once and stayed
// on the canvas.
template <typename Fill>
PixelSet drawn(Fill fill, glm::ivec2 a, glm::ivec2 b, glm::ivec2 c, int width, int height) {
  Canvas canvas(width, height);
  canvas.enable_write_counts();
  fill(canvas, a, b, c, tri::colors::white);
  CHECK(canvas.outside_writes() == 0);
  CHECK(overdrawn_pixels(canvas).empty());
  return written_pixels(canvas);
}

PixelSet filled(glm::ivec2 a, glm::ivec2 b, glm::ivec2 c, int width, int height) {
  return drawn(fill_triangle_edge_function, a, b, c, width, height);
}

// The pixel centres on the segment p + t d, t0 <= t <= t1, that lie on the canvas.
PixelSet lattice_points(glm::ivec2 p, glm::ivec2 d, int t0, int t1, int width, int height) {
  PixelSet set;
  const int g = std::gcd(std::abs(d.x), std::abs(d.y));
  if (g == 0) {
    if (p.x >= 0 && p.x < width && p.y >= 0 && p.y < height) set.emplace(p.x, p.y);
    return set;
  }
  const glm::ivec2 step = d / g;
  for (int k = t0 * g; k <= t1 * g; ++k) {
    const glm::ivec2 q = p + k * step;
    if (q.x >= 0 && q.x < width && q.y >= 0 && q.y < height) set.emplace(q.x, q.y);
  }
  return set;
}

using tri::ch02::tinyrenderer_triangles;

}  // namespace

TEST_CASE("The fill paints exactly the 16 hand-checked pixels of a small triangle, once each",
          "[05_edge_function][step4][fill]") {
  const PixelSet expected{{0, 0}, {1, 1}, {2, 1}, {3, 1}, {1, 2}, {2, 2}, {3, 2}, {4, 2},
                          {5, 2}, {6, 2}, {2, 3}, {3, 3}, {4, 3}, {2, 4}, {3, 4}, {2, 5}};
  CHECK(filled({0, 0}, {6, 2}, {2, 5}, 8, 7) == expected);
  CHECK(filled({2, 5}, {6, 2}, {0, 0}, 8, 7) == expected);  // clockwise
}

TEST_CASE("The fill covers the inclusive pixels of random triangles in all six vertex orders",
          "[05_edge_function][step4][fill][random]") {
  Random random(5201);
  int clockwise = 0, counter_clockwise = 0;
  for (int i = 0; i < 1000; ++i) {
    const VertexTriple v = random_vertices(random, -8, 40);
    const std::int64_t area = edge_cross(v[0], v[1], v[2]);
    if (area == 0) continue;  // zero area: pinned in its own test
    const PixelSet expected = inclusive_pixels(v[0], v[1], v[2], 32, 32);
    std::array<int, 3> order{0, 1, 2};
    do {
      const glm::ivec2 a = v[order[0]], b = v[order[1]], c = v[order[2]];
      (edge_cross(a, b, c) > 0 ? counter_clockwise : clockwise) += 1;
      REQUIRE(filled(a, b, c, 32, 32) == expected);
    } while (std::next_permutation(order.begin(), order.end()));
  }
  // 995 of the 1000 have non-zero area; each gives three orders of each winding.
  CHECK(clockwise == 3 * 995);
  CHECK(counter_clockwise == 3 * 995);
}

TEST_CASE("The three tinyrenderer triangles cover 2521, 4652 and 666 pixels",
          "[05_edge_function][step4][fill]") {
  const std::array<std::size_t, 3> counts{2521, 4652, 666};
  for (std::size_t i = 0; i < 3; ++i) {
    const auto& [a, b, c] = tinyrenderer_triangles[i].vertices;
    const PixelSet pixels = filled(a, b, c, 200, 200);
    CHECK(pixels.size() == counts[i]);
    CHECK(pixels == inclusive_pixels(a, b, c, 200, 200));
  }
}

TEST_CASE("The published test draws other pixels than the right one on the tinyrenderer triangles",
          "[05_edge_function][step4][fill][published bug]") {
  struct Counts {
    std::size_t right, published, both;
  };
  // Measured: the published test keeps 1037, 1 and 1 of the right pixels and adds 146, 236, 19.
  const std::array<Counts, 3> expected{{{2521, 1183, 1037}, {4652, 237, 1}, {666, 20, 1}}};
  for (std::size_t i = 0; i < 3; ++i) {
    const auto& [a, b, c] = tinyrenderer_triangles[i].vertices;
    const PixelSet right = filled(a, b, c, 200, 200);
    const PixelSet published = drawn(fill_triangle_published_bug, a, b, c, 200, 200);
    const PixelSet both = intersection(right, published);
    CHECK(right.size() == expected[i].right);
    CHECK(published.size() == expected[i].published);
    CHECK(both.size() == expected[i].both);
  }
}

TEST_CASE("The published fill draws 2 pixels of the small triangle",
          "[05_edge_function][step4][fill][published bug]") {
  CHECK(drawn(fill_triangle_published_bug, {0, 0}, {6, 2}, {2, 5}, 8, 7) ==
        PixelSet{{3, 1}, {3, 2}});
}

TEST_CASE("Zero-area triangles draw the pixel centres lying exactly on their segment",
          "[05_edge_function][step4][fill][degenerate]") {
  // tri 0 0 10 10 20 20: the 21 diagonal pixels (0,0) to (20,20).
  PixelSet diagonal;
  for (int i = 0; i <= 20; ++i) diagonal.emplace(i, i);
  CHECK(filled({0, 0}, {10, 10}, {20, 20}, 32, 32) == diagonal);
  CHECK(filled({0, 0}, {0, 0}, {0, 0}, 32, 32) == PixelSet{{0, 0}});
  CHECK(filled({5, 5}, {5, 5}, {15, 10}, 32, 32) ==
        PixelSet{{5, 5}, {7, 6}, {9, 7}, {11, 8}, {13, 9}, {15, 10}});
  CHECK(filled({0, 12}, {10, 15}, {20, 18}, 32, 32) == PixelSet{{0, 12}, {10, 15}, {20, 18}});
  // The chapter's figure (05_zero_area, 24x30): direction (10, 3), only the vertices; one point.
  CHECK(filled({2, 22}, {12, 25}, {22, 28}, 24, 30) == PixelSet{{2, 22}, {12, 25}, {22, 28}});
  CHECK(filled({20, 4}, {20, 4}, {20, 4}, 24, 30) == PixelSet{{20, 4}});
  CHECK(filled({2, 3}, {9, 3}, {5, 3}, 32, 32).size() == 8);    // horizontal
  CHECK(filled({4, 9}, {4, 1}, {4, 40}, 32, 32).size() == 31);  // vertical, clipped above y = 31

  Random random(5202);
  for (int i = 0; i < 500; ++i) {
    const glm::ivec2 p{random.integer(-10, 40), random.integer(-10, 40)};
    const glm::ivec2 d{random.integer(-6, 6), random.integer(-6, 6)};
    std::array<int, 3> t{random.integer(-5, 5), random.integer(-5, 5), random.integer(-5, 5)};
    const PixelSet pixels = filled(p + t[0] * d, p + t[1] * d, p + t[2] * d, 32, 32);
    std::sort(t.begin(), t.end());
    REQUIRE(pixels == lattice_points(p, d, t[0], t[2], 32, 32));
  }
}

TEST_CASE("Every vertex on the canvas is drawn, up to the last row and column",
          "[05_edge_function][traps][fill][box]") {
  // A `<` in either box loop, or a clamp to the width instead of width - 1, would break this.
  const PixelSet pixels = filled({0, 0}, {31, 31}, {0, 31}, 32, 32);
  CHECK(pixels.count({0, 0}) == 1);
  CHECK(pixels.count({31, 31}) == 1);
  CHECK(pixels.count({0, 31}) == 1);
  CHECK(pixels.size() == 32 * 33 / 2);
}

TEST_CASE("A triangle entirely off the canvas draws nothing",
          "[05_edge_function][step4][fill][box]") {
  CHECK(filled({-30, -50}, {-2, 60}, {-9, 4}, 32, 32).empty());
  CHECK(filled({40, 0}, {50, 10}, {45, 30}, 32, 32).empty());
}

TEST_CASE("Vertices at 1e7 and 2^30 are clipped to the canvas with no outside writes",
          "[05_edge_function][step4][fill][huge]") {
  // Covers the whole canvas.
  CHECK(filled({-two_to_30, -two_to_30}, {two_to_30, -two_to_30}, {0, two_to_30}, 32, 32).size() ==
        32 * 32);
  CHECK(filled({-10'000'000, -10'000'000}, {10'000'000, -10'000'000}, {0, 10'000'000}, 32, 32)
            .size() == 32 * 32);
  // A sliver crossing the canvas.
  const glm::ivec2 a(-two_to_30, 10), b(two_to_30, 12), c(two_to_30, 20);
  const PixelSet sliver = filled(a, b, c, 32, 32);
  CHECK(sliver == inclusive_pixels(a, b, c, 32, 32));
  // Its edges are y = 11 + x / 2^30 and y = 15 + 5x / 2^30: rows 12 to 15 whole, and the one
  // pixel centre (0, 11) that lies exactly on the lower edge.
  CHECK(sliver.size() == 4 * 32 + 1);
  CHECK(sliver.count({0, 11}) == 1);

  Random random(5203);
  for (const int far : {10'000'000, two_to_30}) {
    for (int i = 0; i < 300; ++i) {
      // Two far vertices and one near the canvas, so most triangles cross it.
      const glm::ivec2 p{random.integer(-far, far), random.integer(-far, far)};
      const glm::ivec2 q{random.integer(-far, far), random.integer(-far, far)};
      const glm::ivec2 r{random.integer(-8, 40), random.integer(-8, 40)};
      if (edge_cross(p, q, r) == 0) continue;
      REQUIRE(filled(p, q, r, 32, 32) == inclusive_pixels(p, q, r, 32, 32));
    }
  }
}
