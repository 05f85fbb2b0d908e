#include <algorithm>
#include <cmath>
#include <iterator>
#include <optional>

#include <catch2/catch.hpp>

#include "chapters/06_barycentric/barycentric.hpp"
#include "chapters/06_barycentric/examples.hpp"
#include "chapters/06_barycentric/fill.hpp"
#include "chapters/06_barycentric/random_triangles.hpp"
#include "tests/support/pixels.hpp"

using namespace tri::ch06;
using namespace testing;
using namespace tri::testing;
using tri::Canvas;

namespace {

struct SearchResult {
  int attempt;
  PixelTriangle triangle;
};

// The seeded search that found float_double_disagreement.
std::optional<SearchResult> first_float_double_disagreement() {
  Random random(606);
  for (int attempt = 0; attempt < 100000; ++attempt) {
    const PixelTriangle t = triangle_with_edge_through_canvas(random, 10000, 16);
    if (filled_pixels<float>(t, 16, 16) != filled_pixels<double>(t, 16, 16)) {
      return SearchResult{attempt, t};
    }
  }
  return std::nullopt;
}

}  // namespace

TEST_CASE("A seeded search finds the triangle where float and double fill different pixels",
          "[06_barycentric][step6][06][precision]") {
  const auto found = first_float_double_disagreement();
  REQUIRE(found.has_value());
  CHECK(found->attempt == 3);
  CHECK(found->triangle == float_double_disagreement);
}

TEST_CASE("On the kept triangle double fills the exact set and float misses one edge pixel",
          "[06_barycentric][step6][06][precision]") {
  const auto [a, b, c] = float_double_disagreement;
  const PixelSet exact = inclusive_pixels(a, b, c, 16, 16);
  const PixelSet with_double = filled_pixels<double>({a, b, c}, 16, 16);
  const PixelSet with_float = filled_pixels<float>({a, b, c}, 16, 16);
  CHECK(with_double == exact);
  CHECK(with_double.size() == 67);
  CHECK(with_float.size() == 66);
  // The missing pixel is the midpoint of edge bc: exactly on the edge, where the weight of a is 0.
  CHECK(b + c == 2 * glm::ivec2(15, 11));
  CHECK(minus(with_float, with_double).empty());
  CHECK(minus(with_double, with_float) == PixelSet{{15, 11}});
}

TEST_CASE("Float sees an area of 2^21 in a zero-area triangle 10^7 away and draws 7 pixels",
          "[06_barycentric][step6][06][precision][degenerate]") {
  const auto [a, b, c] = collinear_at_ten_million;
  // Exactly collinear: the 64-bit cross product is 0.
  CHECK((static_cast<long long>(b.x) - a.x) * (static_cast<long long>(c.y) - a.y) ==
        (static_cast<long long>(c.x) - a.x) * (static_cast<long long>(b.y) - a.y));
  CHECK(cross_of_rows<double>(a, b, c, {0, 0}).z == 0);
  // float rounds the differences (beyond 2^24) and the products: the "area" is 2^21 = 2097152,
  // far above any epsilon a guard could use.
  CHECK(cross_of_rows<float>(a, b, c, {0, 0}).z == 2097152.0f);
  CHECK(filled_pixels<double>({a, b, c}, 32, 32).empty());
  const Canvas canvas = filled<float>({a, b, c}, 32, 32);
  CHECK(written_pixels(canvas) ==
        PixelSet{{14, 2}, {15, 8}, {15, 9}, {16, 16}, {17, 22}, {17, 23}, {18, 30}});
  CHECK(canvas.outside_writes() == 0);
}

TEST_CASE("At 10^7 and 2^30 float weights stay finite and the fill stays on the canvas",
          "[06_barycentric][float_vs_double][06][precision]") {
  Random random(607);
  for (const int reach : {10'000'000, (1 << 30) - 64}) {
    for (int i = 0; i < 100; ++i) {
      const PixelTriangle t = triangle_with_edge_through_canvas(random, reach, 32);
      int non_finite = 0;
      for (int y = 0; y < 32; ++y) {
        for (int x = 0; x < 32; ++x) {
          const auto w = barycentric<float>(t[0], t[1], t[2], {x, y});
          if (!std::isfinite(w.x) || !std::isfinite(w.y) || !std::isfinite(w.z)) ++non_finite;
        }
      }
      CHECK(non_finite == 0);
      const Canvas canvas = filled<float>(t, 32, 32);
      CHECK(canvas.outside_writes() == 0);
      CHECK(overdrawn_pixels(canvas).empty());
    }
  }
}
