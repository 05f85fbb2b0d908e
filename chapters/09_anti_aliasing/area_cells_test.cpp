#include "chapters/09_anti_aliasing/area_cells.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "chapters/09_anti_aliasing/area_oracle.hpp"
#include "chapters/09_anti_aliasing/test_triangles.hpp"

namespace tri::ch09 {

namespace {

using tri::ch08::InstructionSet;

// The largest |canvas - exact| over every pixel of the canvas, for one triangle drawn alone;
// summed, through the row loop's copy for `set` (by default the widest the host runs).
double largest_difference(const Triangle& t, int width, int height, Blend blend = Blend::sum,
                          InstructionSet set = tri::ch08::widest_instruction_set()) {
  CoverageCanvas canvas(width, height);
  RowCells cells;
  draw_triangle_area(canvas, t, cells, blend, set);
  double largest = 0;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const double exact = exact_coverage(t, {x, y}).to_double();
      largest = std::max(largest, std::abs(canvas.at(x, y) - exact));
    }
  }
  return largest;
}

// The triangle's vertices, for the message of a failed check.
std::string describe(const Triangle& t) {
  std::ostringstream text;
  text << "(" << t[0].x << ", " << t[0].y << ") (" << t[1].x << ", " << t[1].y << ") (" << t[2].x
       << ", " << t[2].y << ")";
  return text.str();
}

// Each triangle drawn alone on a 12 x 12 canvas: every pixel within 1e-6 of the exact area, well
// within one unit of the 16-bit output, 1/65535.
void check_against_oracle(const std::vector<Triangle>& triangles, Blend blend = Blend::sum,
                          InstructionSet set = tri::ch08::widest_instruction_set()) {
  for (std::size_t trial = 0; trial < triangles.size(); ++trial) {
    INFO("trial " << trial << ": " << describe(triangles[trial]));
    CHECK(largest_difference(triangles[trial], 12, 12, blend, set) < 1e-6);
  }
}

// The triangle wound counter-clockwise (y up), as the row cells walk it.
Triangle counter_clockwise(const Triangle& t) {
  const glm::dvec2 ab = t[1] - t[0], ac = t[2] - t[0];
  return ab.x * ac.y - ab.y * ac.x >= 0 ? t : Triangle{{t[0], t[2], t[1]}};
}

}  // namespace

TEST_CASE("Step 1 measures each edge piece from the pixel's left side, the cells to its right side",
          "[09_anti_aliasing][step4]") {
  for (const Triangle& random : test::random_triangles(60, 43, {1, 1}, {9, 9})) {
    const Triangle t = counter_clockwise(random);
    INFO(describe(t));
    for (int row = 0; row <= 10; ++row) {
      RowCells cells;
      cells.start_row(12);
      add_edges_in_row(cells, t, row);
      double running_cover = 0;
      for (int x = 0; x <= 10; ++x) {
        running_cover += cells.cover(x);
        Fraction from_left = 0, area = 0, cover = 0;
        for (std::size_t k = 0; k < 3; ++k) {
          const glm::dvec2 a = t[k], b = t[(k + 1) % 3];
          const EdgeInPixelRow parts = edge_in_pixel_row(a, b, {x, row});
          CHECK(edge_area_in_pixel(a, b, {x, row}) == parts.from_left());  // step 1: from the left
          from_left = from_left + parts.from_left();
          area = area + parts.area();
          cover = cover + parts.cover();
        }
        const Fraction coverage = exact_coverage(t, {x, row});
        CHECK(from_left == coverage);                              // counter-clockwise: +coverage
        CHECK(area + cover == Fraction(0) - coverage);             // the mirror: -coverage
        CHECK(std::abs(cells.area(x) - area.to_double()) < 1e-9);  // step 4: to the right side
        CHECK(std::abs(running_cover - cover.to_double()) < 1e-9);
      }
    }
  }
}

TEST_CASE("The row cells give each pixel the exact area, within a float's rounding",
          "[09_anti_aliasing][step4]") {
  check_against_oracle(test::random_triangles(300, 42, {-2, -2}, {14, 14}));
}

TEST_CASE("Edges on pixel sides, vertical and horizontal edges, and vertices on corners",
          "[09_anti_aliasing][step4]") {
  const std::vector<Triangle> cases = {
      {{{-0.5, -0.5}, {3.5, -0.5}, {-0.5, 3.5}}},  // sides and corners of pixels
      {{{1, 1}, {1, 6}, {5, 1}}},                  // vertical and horizontal through centres
      {{{0.5, 0.5}, {4.5, 0.5}, {0.5, 4.5}}},      // vertices on pixel corners
      {{{2, -3}, {2.00390625, 9}, {-4, 3}}},       // a near-vertical edge, off the canvas
      {{{-30, -30}, {40, -29.5}, {5, 40}}},        // larger than the canvas on every side
      {{{3.25, 3.25}, {3.5, 3.25}, {3.25, 3.5}}},  // inside one pixel
      {{{0, 0}, {7.99609375, 0.00390625}, {0, 0.0078125}}},  // a sliver along a row
  };
  for (const auto& t : cases) {
    INFO(describe(t));
    CHECK(largest_difference(t, 8, 8) < 1e-6);
    // Either winding gives the same picture.
    CHECK(largest_difference({{t[0], t[2], t[1]}}, 8, 8) < 1e-6);
  }
}

TEST_CASE("Triangles reaching past every edge of the canvas get the exact area on it",
          "[09_anti_aliasing][step4]") {
  // Vertices up to 20 pixels off a 12 x 12 canvas: rows where a side lies wholly left or right of
  // the canvas, or crosses its left or right edge, and rows above and below it.
  check_against_oracle(test::random_triangles(300, 43, {-20, -20}, {32, 32}));
}

TEST_CASE("Slivers whose two sides share the same cells get the exact area",
          "[09_anti_aliasing][step4]") {
  // Needles 1/256 of a pixel thick at many angles: in every row both sides cross the same cells.
  std::vector<Triangle> needles;
  for (const Triangle& t : test::random_triangles(200, 44, {0, 0}, {12, 12})) {
    needles.push_back({{t[0], t[1], t[1] + glm::dvec2{1 / 256.0, 0}}});
  }
  check_against_oracle(needles);
}

TEST_CASE("The portable copy of the summed row loop gives the exact area too",
          "[09_anti_aliasing][step4]") {
  // On a host with AVX2 the tests above run the copy with groups of eight; this is the other one.
  check_against_oracle(test::random_triangles(300, 42, {-2, -2}, {14, 14}), Blend::sum,
                       InstructionSet::portable);
  check_against_oracle(test::random_triangles(300, 43, {-20, -20}, {32, 32}), Blend::sum,
                       InstructionSet::portable);
  std::vector<Triangle> needles;
  for (const Triangle& t : test::random_triangles(200, 44, {0, 0}, {12, 12})) {
    needles.push_back({{t[0], t[1], t[1] + glm::dvec2{1 / 256.0, 0}}});
  }
  check_against_oracle(needles, Blend::sum, InstructionSet::portable);
}

TEST_CASE("On a wide canvas, runs of whole groups between the sides get the exact area",
          "[09_anti_aliasing][step4]") {
  // 40 x 40: bands wider than two groups of eight between the sides, groups that end at the
  // canvas's right edge, and sides off it; in both copies of the row loop.
  for (const Triangle& t : test::random_triangles(60, 46, {-6, -6}, {46, 46})) {
    INFO(describe(t));
    CHECK(largest_difference(t, 40, 40) < 1e-6);
    CHECK(largest_difference(t, 40, 40, Blend::sum, InstructionSet::portable) < 1e-6);
  }
}

TEST_CASE("Both copies of the summed row loop give every pixel the same bits",
          "[09_anti_aliasing][step4]") {
  // The playground's WebAssembly has only the portable copy and must draw what raster draws.
  for (const InstructionSet set : tri::ch08::all_instruction_sets) {
    if (!tri::ch08::host_runs(set)) continue;
    INFO("copy " << static_cast<int>(set));
    for (const Triangle& t : test::random_triangles(500, 47, {-6, -6}, {46, 46})) {
      INFO(describe(t));
      CoverageCanvas forced(40, 40), portable(40, 40);
      RowCells cells;
      draw_triangle_area(forced, t, cells, Blend::sum, set);
      draw_triangle_area(portable, t, cells, Blend::sum, InstructionSet::portable);
      int differing = 0;
      for (int y = 0; y < 40; ++y) {
        for (int x = 0; x < 40; ++x) differing += forced.at(x, y) != portable.at(x, y);
      }
      CHECK(differing == 0);
    }
  }
}

TEST_CASE("area_lane_floats is 8 on a host with AVX2 and 4 without", "[09_anti_aliasing][step4]") {
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
  const int expected = __builtin_cpu_supports("avx2") ? 8 : 4;
  CHECK(area_lane_floats() == expected);
#else
  CHECK(area_lane_floats() == 4);
#endif
}

TEST_CASE("Composited over an empty canvas, a triangle gives each pixel its exact area",
          "[09_anti_aliasing][step5]") {
  // Over an empty pixel, v + c (1 - v) is c: the composited drawing, which takes the cells
  // wherever the sides share a cell or a row holds the middle vertex, must equal the exact area.
  check_against_oracle(test::random_triangles(300, 45, {-2, -2}, {14, 14}), Blend::over);
}

TEST_CASE("A zero-area or non-finite triangle adds nothing", "[09_anti_aliasing][step4]") {
  CoverageCanvas canvas(4, 4);
  RowCells cells;
  draw_triangle_area(canvas, {{{0, 0}, {2, 2}, {3, 3}}}, cells);
  draw_triangle_area(canvas, {{{0, 0}, {NAN, 2}, {3, 0}}}, cells);
  draw_triangle_area(canvas, {{{0, 0}, {INFINITY, 2}, {3, 0}}}, cells);
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 4; ++x) CHECK(canvas.at(x, y) == 0.0f);
  }
}

TEST_CASE("The 16-bit PGM of a coverage canvas: header, top row first, big-endian, rounded",
          "[09_anti_aliasing][step4]") {
  CoverageCanvas canvas(2, 2);
  canvas.add(0, 1, 1.0f);   // top left: full
  canvas.add(1, 1, 0.5f);   // top right: 32767.5 rounds up
  canvas.add(0, 0, 1.75f);  // bottom left: clamped to 1
  const std::vector<std::uint8_t> pgm = canvas.pgm_16();
  const std::string header = "P5\n2 2\n65535\n";
  REQUIRE(pgm.size() == header.size() + 8);
  CHECK(std::string(pgm.begin(), pgm.begin() + static_cast<long>(header.size())) == header);
  const auto value = [&](std::size_t k) {
    return (pgm[header.size() + 2 * k] << 8) | pgm[header.size() + 2 * k + 1];
  };
  CHECK(value(0) == 65535);
  CHECK(value(1) == 32768);
  CHECK(value(2) == 65535);
  CHECK(value(3) == 0);
}

}  // namespace tri::ch09
