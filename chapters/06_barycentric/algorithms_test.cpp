#include <string_view>

#include <catch2/catch.hpp>

#include "chapters/06_barycentric/algorithms.hpp"
#include "chapters/06_barycentric/fill.hpp"
#include "chapters/06_barycentric/random_triangles.hpp"
#include "tests/support/registry_checks.hpp"

using namespace tri;
using namespace tri::ch06;
using namespace tri::ch06::testing;
using namespace tri::testing;

namespace {

Triangle as_doubles(const PixelTriangle& t) {
  return {glm::dvec2(t[0]), glm::dvec2(t[1]), glm::dvec2(t[2])};
}

// Pixels the algorithm misses and adds against inclusive_pixels, summed over a set of triangles.
struct Deviation {
  int triangles = 0;  ///< triangles with at least one wrong pixel
  long long missed = 0;
  long long extra = 0;
  long long covered = 0;  ///< pixels of inclusive_pixels, summed
  std::uint64_t outside_writes = 0;
};

Deviation measure(const TriangleAlgorithm& algorithm, const std::vector<PixelTriangle>& triangles,
                  int size) {
  Deviation deviation;
  for (const PixelTriangle& t : triangles) {
    Canvas canvas(size, size);
    canvas.enable_write_counts();
    REQUIRE(draw_triangle(algorithm, canvas, as_doubles(t), colors::white) == DrawResult::drawn);
    const PixelSet drawn = written_pixels(canvas);
    const PixelSet exact = inclusive_pixels(t[0], t[1], t[2], size, size);
    long long missed = 0, extra = 0;
    for (const auto& p : exact) missed += drawn.count(p) == 0 ? 1 : 0;
    for (const auto& p : drawn) extra += exact.count(p) == 0 ? 1 : 0;
    deviation.triangles += missed + extra > 0 ? 1 : 0;
    deviation.missed += missed;
    deviation.extra += extra;
    deviation.covered += static_cast<long long>(exact.size());
    deviation.outside_writes += canvas.outside_writes();
  }
  return deviation;
}

std::vector<PixelTriangle> triangles_on_canvas(std::uint64_t seed, int count, int size) {
  Random random(seed);
  std::vector<PixelTriangle> triangles;
  for (int i = 0; i < count; ++i) triangles.push_back(random_vertices(random, 0, size - 1));
  return triangles;
}

std::vector<PixelTriangle> triangles_reaching(std::uint64_t seed, int count, int reach, int size) {
  Random random(seed);
  std::vector<PixelTriangle> triangles;
  for (int i = 0; i < count; ++i) {
    triangles.push_back(triangle_with_edge_through_canvas(random, reach, size));
  }
  return triangles;
}

}  // namespace

TEST_CASE("Chapter 06 registers barycentric_float and barycentric_double",
          "[06_barycentric][step6][06][registry]") {
  check_chapter_entries(ch06::triangle_algorithms(), "06_barycentric",
                        {"barycentric_float", "barycentric_double"}, CoverageRule::approximate);
}

TEST_CASE("The registered algorithms round the vertices to the nearest pixel centre",
          "[06_barycentric][step6][06][registry]") {
  for (const TriangleAlgorithm& algorithm : ch06::triangle_algorithms()) {
    Canvas canvas(8, 8);
    canvas.enable_write_counts();
    // Rounds to the hand-checked triangle (1,1), (6,2), (3,5).
    draw_triangle(algorithm, canvas, {{{0.5, 1.49}, {6.4, 1.5}, {2.6, 5.2}}}, colors::white);
    CHECK(written_pixels(canvas) ==
          inclusive_pixels({1, 1}, {6, 2}, {3, 5}, canvas.width(), canvas.height()));
  }
}

TEST_CASE("Both algorithms cover exactly the inclusive pixels on a 256x256 canvas",
          "[06_barycentric][step6][06][registry][deviation]") {
  const auto triangles = triangles_on_canvas(608, 200, 256);
  for (const TriangleAlgorithm& algorithm : ch06::triangle_algorithms()) {
    const Deviation deviation = measure(algorithm, triangles, 256);
    INFO(algorithm.name);
    CHECK(deviation.covered == 993566);
    CHECK(deviation.triangles == 0);
    CHECK(deviation.outside_writes == 0);
  }
}

TEST_CASE("Far outside the canvas float deviates from 10^4 on, double only beyond 2^24",
          "[06_barycentric][step6][06][registry][deviation]") {
  const TriangleAlgorithm& with_float =
      algorithm_named(ch06::triangle_algorithms(), "barycentric_float");
  const TriangleAlgorithm& with_double =
      algorithm_named(ch06::triangle_algorithms(), "barycentric_double");
  struct Expected {
    int reach;
    long long covered;
    int float_triangles, float_missed, float_extra;
    int double_triangles, double_missed, double_extra;
  };
  // 300 triangles per reach on a 64x64 canvas, each with an edge through a pixel centre. Within
  // +-2^24 every product double forms is below 2^50 and every sum below 2^52: all exact.
  const Expected table[] = {
      {10'000, 582467, 64, 59, 5, 0, 0, 0},
      {10'000'000, 616386, 296, 690, 4502, 0, 0, 0},
      {(1 << 24) - 128, 627867, 297, 1225, 8295, 0, 0, 0},
      {100'000'000, 629767, 300, 10839, 54250, 11, 11, 0},
      {(1 << 30) - 128, 645034, 299, 73055, 299553, 47, 47, 0},
  };
  for (const Expected& expected : table) {
    INFO("reach " << expected.reach);
    const auto triangles = triangles_reaching(609, 300, expected.reach, 64);
    const Deviation f = measure(with_float, triangles, 64);
    const Deviation d = measure(with_double, triangles, 64);
    CHECK(f.covered == expected.covered);
    CHECK(f.triangles == expected.float_triangles);
    CHECK(f.missed == expected.float_missed);
    CHECK(f.extra == expected.float_extra);
    CHECK(d.triangles == expected.double_triangles);
    CHECK(d.missed == expected.double_missed);
    CHECK(d.extra == expected.double_extra);
    CHECK(f.outside_writes == 0);
    CHECK(d.outside_writes == 0);
  }
}

TEST_CASE("Degenerate and huge triangles draw safely through the registry",
          "[06_barycentric][step6][06][registry]") {
  constexpr double huge = 1 << 30;
  for (const TriangleAlgorithm& algorithm : ch06::triangle_algorithms()) {
    INFO(algorithm.name);
    Canvas canvas(32, 32);
    canvas.enable_write_counts();
    draw_triangle(algorithm, canvas, {{{0, 0}, {0, 0}, {0, 0}}}, colors::white);
    draw_triangle(algorithm, canvas, {{{2, 3}, {10, 3}, {30, 3}}}, colors::white);
    draw_triangle(algorithm, canvas, {{{1, 1}, {5, 9}, {7, 13}}}, colors::white);
    CHECK(written_pixels(canvas).empty());
    draw_triangle(algorithm, canvas, {{{-huge, -huge}, {huge, -huge}, {0, huge}}}, colors::white);
    CHECK(written_pixels(canvas).size() == 32 * 32);
    CHECK(canvas.outside_writes() == 0);
  }
}
