// Chapter 09's algorithms at the edges of the number line: vertices a subnormal distance apart,
// slopes whose quotients overflow, nearly parallel edges at ±2^30, zero and near-zero area.
#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include <glm/common.hpp>

#include "chapters/09_anti_aliasing/area_algorithms.hpp"
#include "chapters/09_anti_aliasing/area_cells.hpp"
#include "chapters/09_anti_aliasing/area_oracle.hpp"
#include "chapters/09_anti_aliasing/sampling.hpp"

namespace tri::ch09 {
namespace {

constexpr int side = 16;                           // every scene here is drawn on a 16 x 16 canvas
constexpr double limit = 1073741824.0;             // 2^30, the scene format's largest coordinate
constexpr double subnormal = 1e-310;               // below the least normal double, 2.2e-308
constexpr double least = 4.9406564584124654e-324;  // the least double above 0, 2^-1074

std::string describe(const Triangle& t) {
  std::ostringstream text;
  text.precision(17);
  text << "(" << t[0].x << ", " << t[0].y << ") (" << t[1].x << ", " << t[1].y << ") (" << t[2].x
       << ", " << t[2].y << ")";
  return text.str();
}

// The triangle moved to the nearest 1/256-grid points: the offsets below are far smaller than
// that grid, so this is the triangle the oracle can take, and the sampling algorithms' own.
Triangle on_grid(const Triangle& t) {
  Triangle snapped;
  for (std::size_t k = 0; k < 3; ++k) snapped[k] = glm::round(t[k] * 256.0) / 256.0;
  return snapped;
}

// Triangles whose vertices differ by amounts whose products or quotients leave the range of
// doubles: each is a 1/256-grid triangle moved by at most 2^-50, so its exact coverage differs
// from the grid triangle's by less than 1e-13 per pixel (at most the moves times the perimeter).
std::vector<Triangle> subnormal_scenes() {
  return {
      {{{15, 0}, {subnormal, subnormal}, {0, 15}}},      // area_cells_over spun and crashed
      {{{15, 0}, {0, 0}, {subnormal, 15}}},              // area_cells: (1, 13) was 0, not 65535
      {{{0, 0}, {10, 5}, {least, 10}}},                  // area_cells: (1, 1) was 0, not 61439
      {{{0, 15}, {0, 0}, {15, 0}}},                      // the first's grid triangle, for contrast
      {{{0, 15}, {subnormal, 15}, {15, 0}}},             // a flat top a subnormal wide
      {{{15, 0}, {0, 0}, {-subnormal, 15}}},             // leaning left, clockwise
      {{{0.125, 3e-308}, {0, 0}, {0, 12}}},              // normal numbers whose product underflows
      {{{0, 0}, {1e-160, 1e-160}, {15, 14}}},            // dx dy = 1e-320: its inverse is infinite
      {{{3, 2}, {3 + 0x1p-50, 14}, {12, 2 + 0x1p-50}}},  // near-vertical and near-flat edges
      {{{0, 0}, {15, subnormal}, {7, 2 * subnormal}}},   // all in one subnormal row: area 0
      {{{0, 0}, {subnormal, 15}, {2 * subnormal, 7}}},   // all in one subnormal column: area 0
      {{{0, 0}, {15, least}, {15, 2 * least}}},          // the least area a double can hold
  };
}

// Every pixel of the canvas after the algorithm drew the triangle alone.
CoverageCanvas drawn(const AreaAlgorithm& algorithm, const Triangle& t) {
  CoverageCanvas canvas(side, side);
  const std::vector<SceneTriangle> scene = {{t}};
  REQUIRE(draw_coverage(algorithm, canvas, scene) == 0);
  return canvas;
}

// How many pixels differ from the truth: the exact area (within 1e-6, the chapter's promise for
// the area algorithms) or the exact count of the algorithm's own samples (equal).
int wrong_pixels(const AreaAlgorithm& algorithm, const Triangle& t, const Triangle& truth) {
  const CoverageCanvas canvas = drawn(algorithm, t);
  int wrong = 0;
  for (int y = 0; y < side; ++y) {
    for (int x = 0; x < side; ++x) {
      const double expected = algorithm.samples == 0
                                  ? exact_coverage(truth, {x, y}).to_double()
                                  : snapped_sampled_coverage(t, {x, y}, algorithm.sample_pattern());
      const double tolerance = algorithm.samples == 0 ? 1e-6 : 0;
      wrong += !(std::abs(canvas.at(x, y) - expected) <= tolerance);
    }
  }
  return wrong;
}

}  // namespace

TEST_CASE("Every coverage algorithm is right on vertices a subnormal distance apart",
          "[09_anti_aliasing][step4]") {
  for (const AreaAlgorithm& algorithm : area_algorithms()) {
    for (const Triangle& t : subnormal_scenes()) {
      INFO(algorithm.name << " on " << describe(t));
      CHECK(wrong_pixels(algorithm, t, on_grid(t)) == 0);
    }
  }
}

TEST_CASE("The reported subnormal scenes give the 16-bit values of their grid triangles",
          "[09_anti_aliasing][step4]") {
  const auto scenes = subnormal_scenes();
  for (const AreaAlgorithm& algorithm : area_algorithms()) {
    if (algorithm.samples != 0) continue;
    INFO(algorithm.name);
    CHECK(coverage_16(drawn(algorithm, scenes[1]).at(1, 13)) == 65535);
    CHECK(coverage_16(drawn(algorithm, scenes[2]).at(1, 1)) == 61439);
    CHECK(coverage_16(drawn(algorithm, scenes[0]).at(1, 13)) == 65535);
  }
}

TEST_CASE("Triangles with vertices at 2^30 get the exact area on the canvas",
          "[09_anti_aliasing][step4]") {
  // Covering the whole canvas: every pixel exactly 1, for every algorithm.
  const Triangle huge = {{{-limit, -limit}, {limit, -limit}, {0, limit}}};
  // A sliver along row 0 whose long edges are nearly parallel: between y = 0 and the line from
  // (-2^30, 0) to (2^30, 1/256), y = (x + 2^30) / 2^39. Pixel (i, 0) holds the integral of that
  // line over [i - 1/2, i + 1/2]: (i + 2^30) / 2^39 exactly; every other row holds nothing.
  const Triangle sliver = {{{-limit, 0}, {limit, 0}, {limit, 1.0 / 256}}};
  // The same sliver tipped on its side: column 0 holds (j + 2^30) / 2^39.
  const Triangle standing = {{{0, -limit}, {0, limit}, {-1.0 / 256, limit}}};
  for (const AreaAlgorithm& algorithm : area_algorithms()) {
    INFO(algorithm.name);
    const CoverageCanvas whole = drawn(algorithm, huge), flat = drawn(algorithm, sliver),
                         tall = drawn(algorithm, standing);
    int wrong = 0;
    for (int y = 0; y < side; ++y) {
      for (int x = 0; x < side; ++x) {
        wrong += whole.at(x, y) != 1.0f;
        if (algorithm.samples == 0) {
          const double along_row = y == 0 ? (x + limit) / 0x1p39 : 0;
          const double along_column = x == 0 ? (y + limit) / 0x1p39 : 0;
          wrong += !(std::abs(flat.at(x, y) - along_row) <= 1e-6);
          wrong += !(std::abs(tall.at(x, y) - along_column) <= 1e-6);
        } else {
          const SamplePattern pattern = algorithm.sample_pattern();
          wrong += flat.at(x, y) != snapped_sampled_coverage(sliver, {x, y}, pattern);
          wrong += tall.at(x, y) != snapped_sampled_coverage(standing, {x, y}, pattern);
        }
      }
    }
    CHECK(wrong == 0);
  }
}

TEST_CASE("A triangle beyond 2^30 or not finite adds nothing, drawn directly",
          "[09_anti_aliasing][step4]") {
  const double nan = std::nan("");
  for (const Triangle& t :
       {Triangle{{{0, 0}, {4 * limit, 0}, {0, 8}}}, Triangle{{{0, 0}, {8, 0}, {0, -4 * limit}}},
        Triangle{{{0, 0}, {8, 0}, {0, nan}}}, Triangle{{{0, 0}, {8, 0}, {0, INFINITY}}}}) {
    INFO(describe(t));
    for (const Blend blend : {Blend::sum, Blend::over}) {
      CoverageCanvas canvas(side, side);
      RowCells cells;
      draw_triangle_area(canvas, t, cells, blend);
      int written = 0;
      for (int y = 0; y < side; ++y) {
        for (int x = 0; x < side; ++x) written += canvas.at(x, y) != 0.0f;
      }
      CHECK(written == 0);
    }
  }
}

}  // namespace tri::ch09
