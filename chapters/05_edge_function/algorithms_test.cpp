#include <algorithm>
#include <array>

#include <catch2/catch.hpp>

#include "chapters/05_edge_function/algorithms.hpp"
#include "tests/support/pixels.hpp"

using tri::Canvas;
using tri::DrawResult;
using tri::Triangle;
using tri::testing::inclusive_pixels;
using tri::testing::PixelSet;

namespace {

constexpr double two_to_30 = 1073741824.0;

const tri::TriangleAlgorithm& edge_function() {
  const auto algorithms = tri::ch05::triangle_algorithms();
  REQUIRE(algorithms.size() == 1);
  return algorithms.front();
}

// What the registered algorithm draws through the library entry point on a fresh 32x32 canvas;
// checks that it drew, stayed on the canvas and wrote no pixel twice.
PixelSet drawn(const Triangle& triangle, int size = 32) {
  Canvas canvas(size, size);
  canvas.enable_write_counts();
  REQUIRE(tri::draw_triangle(edge_function(), canvas, triangle, tri::colors::white) ==
          DrawResult::drawn);
  CHECK(canvas.outside_writes() == 0);
  CHECK(tri::testing::overdrawn_pixels(canvas).empty());
  return tri::testing::written_pixels(canvas);
}

}  // namespace

TEST_CASE("Chapter 05 registers edge_function as an inclusive algorithm",
          "[05_edge_function][step4][registry]") {
  const tri::TriangleAlgorithm& algorithm = edge_function();
  CHECK(algorithm.name == "edge_function");
  CHECK(algorithm.chapter == "05_edge_function");
  CHECK(algorithm.rule == tri::CoverageRule::inclusive);
  CHECK_FALSE(algorithm.summary.empty());
  CHECK_FALSE(algorithm.threaded);
}

TEST_CASE("edge_function covers exactly the inclusive pixels of random integer triangles",
          "[05_edge_function][step4][registry][random]") {
  tri::testing::Random random(5301);
  int tested = 0;
  for (int i = 0; i < 3000; ++i) {
    std::array<glm::ivec2, 3> v{};
    for (auto& vertex : v) vertex = {random.integer(-8, 40), random.integer(-8, 40)};
    if (tri::testing::doubled_area(v[0], v[1], v[2]) == 0) continue;
    const Triangle triangle{glm::dvec2(v[0]), glm::dvec2(v[1]), glm::dvec2(v[2])};
    REQUIRE(drawn(triangle) == inclusive_pixels(v[0], v[1], v[2], 32, 32));
    ++tested;
  }
  CHECK(tested == 2988);  // the other 12 have zero area
}

TEST_CASE("edge_function rounds each vertex to the nearest pixel centre first",
          "[05_edge_function][step4][registry]") {
  tri::testing::Random random(5302);
  for (int i = 0; i < 500; ++i) {
    Triangle triangle{};
    for (auto& vertex : triangle) vertex = {random.real(-8, 40), random.real(-8, 40)};
    const glm::ivec2 a = tri::nearest_pixel(triangle[0]), b = tri::nearest_pixel(triangle[1]),
                     c = tri::nearest_pixel(triangle[2]);
    if (tri::testing::doubled_area(a, b, c) == 0) continue;
    REQUIRE(drawn(triangle) == inclusive_pixels(a, b, c, 32, 32));
  }
  // 2.5 rounds up to 3 and 0.49 down to 0.
  CHECK(drawn({glm::dvec2(0.49, 0), glm::dvec2(2.5, 0), glm::dvec2(0, 2.5)}) ==
        inclusive_pixels({0, 0}, {3, 0}, {0, 3}, 32, 32));
}

TEST_CASE("edge_function draws the pixel centres on a zero-area triangle's segment",
          "[05_edge_function][step4][registry][degenerate]") {
  // The truth (docs/DESIGN.md section 6) covers nothing here; the inclusive sign test covers the
  // pixel centres on the segment. Pinned as a documented deviation.
  PixelSet diagonal;
  for (int i = 0; i <= 20; ++i) diagonal.emplace(i, i);
  CHECK(drawn({glm::dvec2(0, 0), glm::dvec2(10, 10), glm::dvec2(20, 20)}) == diagonal);
  CHECK(drawn({glm::dvec2(0, 0), glm::dvec2(0, 0), glm::dvec2(0, 0)}) == PixelSet{{0, 0}});
  CHECK(drawn({glm::dvec2(3, 7), glm::dvec2(3, 7), glm::dvec2(12, 7)}).size() == 10);
}

TEST_CASE("edge_function stays on the canvas for vertices at 1e7 and 2^30",
          "[05_edge_function][step4][registry][huge]") {
  for (const double far : {1e7, two_to_30}) {
    CHECK(drawn({glm::dvec2(-far, -far), glm::dvec2(far, -far), glm::dvec2(0, far)}).size() ==
          32 * 32);
    CHECK(drawn({glm::dvec2(0, far), glm::dvec2(far, -far), glm::dvec2(-far, -far)}).size() ==
          32 * 32);
    const Triangle sliver{glm::dvec2(-far, 3), glm::dvec2(far, 5), glm::dvec2(-far, 4)};
    CHECK(drawn(sliver) == inclusive_pixels(tri::nearest_pixel(sliver[0]),
                                            tri::nearest_pixel(sliver[1]),
                                            tri::nearest_pixel(sliver[2]), 32, 32));
    CHECK(drawn({glm::dvec2(far, far), glm::dvec2(far, -far), glm::dvec2(far, 0)}).empty());
  }
}
