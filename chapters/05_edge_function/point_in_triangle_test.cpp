#include <algorithm>
#include <array>

#include <catch2/catch.hpp>

#include "chapters/02_wireframe/example_triangles.hpp"
#include "chapters/05_edge_function/cross_product.hpp"
#include "chapters/05_edge_function/point_in_triangle.hpp"
#include "tests/support/pixels.hpp"

using namespace tri::ch05;
using namespace tri::testing;

namespace {

// Every pixel of a width x height grid that passes the test.
template <typename Test>
PixelSet pixels_passing(int width, int height, Test test) {
  PixelSet set;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      if (test(glm::ivec2(x, y))) set.emplace(x, y);
    }
  }
  return set;
}

// The chapter's hand-checked triangle, counter-clockwise (y up); row by row in the README.
const glm::ivec2 a(0, 0), b(6, 2), c(2, 5);
const PixelSet hand_checked_pixels{{0, 0}, {1, 1}, {2, 1}, {3, 1}, {1, 2}, {2, 2}, {3, 2}, {4, 2},
                                   {5, 2}, {6, 2}, {2, 3}, {3, 3}, {4, 3}, {2, 4}, {3, 4}, {2, 5}};

}  // namespace

TEST_CASE("The sign test accepts three values of one sign, zeros included, and nothing mixed",
          "[05_edge_function][step3][inside]") {
  CHECK(same_sign_or_zero({1, 2, 3}));
  CHECK(same_sign_or_zero({-1, -2, -3}));
  CHECK(same_sign_or_zero({0, 2, 3}));
  CHECK(same_sign_or_zero({0, -2, 0}));
  CHECK(same_sign_or_zero({0, 0, 0}));
  CHECK_FALSE(same_sign_or_zero({1, -2, 3}));
  CHECK_FALSE(same_sign_or_zero({-1, 0, 3}));
}

TEST_CASE("The inside test picks exactly the hand-checked pixels of a small triangle",
          "[05_edge_function][step3][inside]") {
  const PixelSet inside =
      pixels_passing(8, 7, [](glm::ivec2 p) { return inside_triangle(a, b, c, p); });
  CHECK(inside == hand_checked_pixels);
  // Pick's theorem agrees: area 13, 4 lattice points on the edges, 12 inside: 16 in all.
  CHECK(edge_cross(a, b, c) == 26);
}

TEST_CASE("The inside test includes the vertices and the pixel centres on the edges",
          "[05_edge_function][step3][inside]") {
  for (const glm::ivec2 vertex : {a, b, c}) CHECK(inside_triangle(a, b, c, vertex));
  CHECK(inside_triangle(a, b, c, {3, 1}));        // on AB
  CHECK_FALSE(inside_triangle(a, b, c, {4, 1}));  // just right of AB
}

TEST_CASE("The inside test answers the same for both windings and all six vertex orders",
          "[05_edge_function][step3][inside]") {
  Random random(5101);
  for (int i = 0; i < 300; ++i) {
    const VertexTriple v = random_vertices(random, -4, 24);
    const PixelSet first =
        pixels_passing(20, 20, [&](glm::ivec2 p) { return inside_triangle(v[0], v[1], v[2], p); });
    std::array<int, 3> order{0, 1, 2};
    while (std::next_permutation(order.begin(), order.end())) {
      const PixelSet other = pixels_passing(20, 20, [&](glm::ivec2 p) {
        return inside_triangle(v[order[0]], v[order[1]], v[order[2]], p);
      });
      REQUIRE(other == first);
    }
  }
}

TEST_CASE("The article's all-non-negative test alone loses every clockwise triangle",
          "[05_edge_function][step3][inside][winding]") {
  // tinyrenderer's first triangle is clockwise with y up: AB x AC < 0.
  // Named copies rather than a structured binding, which lambdas capture only from Clang 16 on.
  const auto& vertices = tri::ch02::tinyrenderer_triangles[0].vertices;
  const glm::ivec2 t0 = vertices[0], t1 = vertices[1], t2 = vertices[2];
  REQUIRE(edge_cross(t0, t1, t2) == -5000);
  const auto all_non_negative = [](glm::i64vec3 e) { return e.x >= 0 && e.y >= 0 && e.z >= 0; };
  CHECK(pixels_passing(200, 200, [&](glm::ivec2 p) {
          return all_non_negative(edge_crosses(t0, t1, t2, p));
        }).empty());
  CHECK(pixels_passing(200, 200, [&](glm::ivec2 p) {
          return all_non_negative(edge_crosses(t0, t2, t1, p));
        }).size() == 2521);
  CHECK(pixels_passing(200, 200, [&](glm::ivec2 p) {
          return inside_triangle(t0, t1, t2, p);
        }).size() == 2521);
}

TEST_CASE("For a zero-area triangle only the points on its line pass",
          "[05_edge_function][step3][inside][degenerate]") {
  // Collinear vertices: the three values sum to 0, so they pass only when all three are 0.
  const glm::ivec2 p0(0, 0), p1(10, 10), p2(20, 20);
  CHECK(inside_triangle(p0, p1, p2, {7, 7}));
  CHECK(inside_triangle(p0, p1, p2, {25, 25}));  // beyond the segment: the bounding box cuts it
  CHECK_FALSE(inside_triangle(p0, p1, p2, {7, 8}));
  // Three equal vertices: all three values are 0 everywhere.
  CHECK(inside_triangle({4, 4}, {4, 4}, {4, 4}, {9, 1}));
}

TEST_CASE("The published inside test keeps 2 of the 16 pixels of the small triangle",
          "[05_edge_function][step3][inside][published bug]") {
  const PixelSet published =
      pixels_passing(8, 7, [](glm::ivec2 p) { return inside_triangle_published_bug(a, b, c, p); });
  CHECK(published == PixelSet{{3, 1}, {3, 2}});
}
