#include "chapters/04_scanline/algorithms.hpp"

#include <catch2/catch.hpp>

#include "tests/support/pixels.hpp"
#include "tests/support/registry_checks.hpp"

using namespace tri;
using namespace tri::testing;

namespace {

const TriangleAlgorithm& registered(std::string_view name) {
  return algorithm_named(ch04::triangle_algorithms(), name);
}

PixelSet drawn(const TriangleAlgorithm& algorithm, const Triangle& triangle, int size = 64) {
  Canvas canvas(size, size);
  canvas.enable_write_counts();
  CHECK(draw_triangle(algorithm, canvas, triangle, colors::white) == DrawResult::drawn);
  CHECK(canvas.outside_writes() == 0);
  return written_pixels(canvas);
}

// Missed and extra pixels against the inclusive truth over seeded random integer triangles of
// non-zero area on a 64x64 canvas, vertices up to 4 pixels beyond its sides.
struct Deviation {
  int triangles = 0;
  std::size_t covered = 0;
  std::size_t missed = 0;
  std::size_t extra = 0;
};

Deviation deviation_on_random_triangles(const TriangleAlgorithm& algorithm) {
  Random random(2024);
  Deviation deviation;
  for (int n = 0; n < 1000; ++n) {
    const VertexTriple v = random_vertices(random, -4, 67);
    const PixelSet truth = inclusive_pixels(v[0], v[1], v[2], 64, 64);
    if (truth.empty()) continue;  // zero area (or entirely off the canvas)
    const PixelSet got = drawn(algorithm, {glm::dvec2(v[0]), glm::dvec2(v[1]), glm::dvec2(v[2])});
    ++deviation.triangles;
    deviation.covered += truth.size();
    for (const auto& p : truth) deviation.missed += got.count(p) == 0 ? 1 : 0;
    for (const auto& p : got) deviation.extra += truth.count(p) == 0 ? 1 : 0;
  }
  return deviation;
}

// The deviation of the registered algorithm `name`, checked field by field against `expected`.
void check_deviation(std::string_view name, const Deviation& expected) {
  const Deviation d = deviation_on_random_triangles(registered(name));
  CHECK(d.triangles == expected.triangles);
  CHECK(d.covered == expected.covered);
  CHECK(d.missed == expected.missed);
  CHECK(d.extra == expected.extra);
}

}  // namespace

TEST_CASE("Chapter 04 registers the two-loop and the single-loop fills as approximate",
          "[04_scanline][algorithms][registry]") {
  check_chapter_entries(ch04::triangle_algorithms(), "04_scanline",
                        {"scanline_two_loops", "scanline_single_loop"}, CoverageRule::approximate);
}

TEST_CASE("The single-loop fill never misses an inclusive pixel and its int casts add extras",
          "[04_scanline][traps][registry][deviation]") {
  check_deviation("scanline_single_loop",
                  {.triangles = 999, .covered = 392828, .missed = 0, .extra = 29776});
}

TEST_CASE("The two-loop fill both misses and adds pixels against the inclusive truth",
          "[04_scanline][traps][registry][deviation]") {
  check_deviation("scanline_two_loops",
                  {.triangles = 999, .covered = 392828, .missed = 9043, .extra = 41734});
}

TEST_CASE("Registered fills round each vertex to its nearest pixel centre",
          "[04_scanline][algorithms][registry]") {
  for (const auto& algorithm : ch04::triangle_algorithms()) {
    const PixelSet exact = drawn(algorithm, {{{0, 0}, {6, 2}, {2, 5}}});
    CHECK(drawn(algorithm, {{{0.4, -0.5}, {5.5, 2.49}, {1.6, 4.5}}}) == exact);
    CHECK(drawn(algorithm, {{{0.5, 0}, {6, 2}, {2, 5}}}) != exact);  // halves round up
  }
}

TEST_CASE("Registered fills draw nothing for a point or a horizontal segment",
          "[04_scanline][algorithms][registry][safety]") {
  for (const auto& algorithm : ch04::triangle_algorithms()) {
    CHECK(drawn(algorithm, {{{0, 0}, {0, 0}, {0, 0}}}).empty());
    CHECK(drawn(algorithm, {{{3, 7}, {30, 7}, {12, 7}}}).empty());
  }
}

TEST_CASE("Registered fills draw a slanted collinear triangle as a thin line of pixels",
          "[04_scanline][algorithms][registry][safety]") {
  // Zero area, so the inclusive truth is empty; the article's fills still draw the diagonal.
  const PixelSet diagonal{{0, 0}, {1, 1}, {2, 2}, {3, 3}, {4, 4}};
  CHECK(drawn(registered("scanline_single_loop"), {{{0, 0}, {2, 2}, {4, 4}}}) == diagonal);
  CHECK(drawn(registered("scanline_two_loops"), {{{0, 0}, {2, 2}, {4, 4}}}).size() == 9);
}

TEST_CASE(
    "Registered fills stay on the canvas and bounded for vertices at plus or minus 1e7 and 2^30",
    "[04_scanline][traps][registry][safety]") {
  for (const double far : {1e7, 1e7 + 0.3, 1073741824.0}) {
    for (const auto& algorithm : ch04::triangle_algorithms()) {
      Canvas canvas(64, 64);
      canvas.enable_write_counts();
      draw_triangle(algorithm, canvas, {{{-far, -far}, {far, -far}, {0, far}}}, colors::white);
      CHECK(canvas.outside_writes() == 0);
      for (const auto count : canvas.write_counts()) CHECK(count == 1);  // covers the canvas once
      canvas.clear(colors::black);
      draw_triangle(algorithm, canvas, {{{-far, -far}, {0, 0}, {far, far}}}, colors::white);
      draw_triangle(algorithm, canvas, {{{far, far}, {-far, far}, {far, -far}}}, colors::white);
      draw_triangle(algorithm, canvas, {{{-far, 0}, {far, 0}, {0, 0}}}, colors::white);
      CHECK(canvas.outside_writes() == 0);
      for (const auto count : canvas.write_counts()) CHECK(count <= 3);
    }
  }
}
