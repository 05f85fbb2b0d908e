#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/common.hpp>

#include "chapters/07_exact_coverage/jittered_mesh.hpp"
#include "chapters/09_anti_aliasing/area_cells.hpp"

namespace tri::ch09 {

namespace {

// A 5x4 mesh of 4-pixel cells from (0.5, 0.5), so it covers pixels 1..20 x 1..16 exactly.
CoverageCanvas mesh_drawn(bool over) {
  CoverageCanvas canvas(22, 18);
  RowCells cells;
  for (const auto& t : ch07::jittered_mesh(5, 4, {0.5, 0.5}, 4, 0.15, 3)) {
    if (over) {
      draw_triangle_area_over(canvas, t, cells);
    } else {
      draw_triangle_area(canvas, t, cells);
    }
  }
  return canvas;
}

}  // namespace

TEST_CASE("Summed coverage covers a mesh's inside exactly once: no seams",
          "[09_anti_aliasing][step5]") {
  const CoverageCanvas canvas = mesh_drawn(false);
  for (int y = 1; y <= 16; ++y) {
    for (int x = 1; x <= 20; ++x) {
      INFO("pixel " << x << ", " << y);
      CHECK(std::abs(canvas.at(x, y) - 1.0f) < 1e-5f);
    }
  }
}

TEST_CASE("Coverage composited as alpha leaves seams along a mesh's shared edges",
          "[09_anti_aliasing][step5]") {
  const CoverageCanvas canvas = mesh_drawn(true);
  int seams = 0;
  float lowest = 1;
  for (int y = 1; y <= 16; ++y) {
    for (int x = 1; x <= 20; ++x) {
      if (canvas.at(x, y) < 1 - 1e-3f) ++seams;
      lowest = std::min(lowest, canvas.at(x, y));
    }
  }
  INFO(seams << " of 320 inner pixels below 1, the lowest " << lowest);
  CHECK(seams > 100);  // every pixel a shared edge crosses
  CHECK(seams == 212);  // the README's count
  CHECK(lowest == Approx(0.67).margin(0.005));
  // With coverages c_k that sum to 1, over gives 1 - (1 - c_1)(1 - c_2)... >= 1 - 1/e.
  CHECK(lowest >= 1 - std::exp(-1.0f));
  CHECK(lowest < 0.8f);
}

TEST_CASE("Two triangles that halve a pixel composite to exactly 0.75 there",
          "[09_anti_aliasing][step5]") {
  CoverageCanvas canvas(4, 4);
  RowCells cells;
  // The diagonal from (-0.5, -0.5) to (3.5, 3.5) runs through pixels (k, k): half each side.
  draw_triangle_area_over(canvas, {{{-0.5, -0.5}, {3.5, -0.5}, {3.5, 3.5}}}, cells);
  draw_triangle_area_over(canvas, {{{-0.5, -0.5}, {3.5, 3.5}, {-0.5, 3.5}}}, cells);
  for (int k = 0; k < 4; ++k) CHECK(canvas.at(k, k) == 0.75f);
  CHECK(canvas.at(1, 0) == 1.0f);
  CHECK(canvas.at(0, 1) == 1.0f);
}

TEST_CASE("Composited over, a fan of 256 triangles still covers its centre pixel at least 1 - 1/e",
          "[09_anti_aliasing][step5]") {
  // 256 triangles around one point of pixel (8, 8), rim vertices on the 1/256 grid and shared.
  const glm::dvec2 centre(8 + 37 / 256.0, 8 - 91 / 256.0);
  const auto on_grid = [](glm::dvec2 p) { return glm::round(p * 256.0) / 256.0; };
  std::vector<glm::dvec2> rim;
  for (int k = 0; k < 256; ++k) {
    const double angle = 2 * 3.141592653589793 * k / 256;
    rim.push_back(on_grid(centre + 6.0 * glm::dvec2(std::cos(angle), std::sin(angle))));
  }
  CoverageCanvas summed(17, 17), over(17, 17);
  RowCells cells;
  for (int k = 0; k < 256; ++k) {
    const Triangle t = {{centre, rim[static_cast<std::size_t>(k)], rim[(k + 1) % 256]}};
    draw_triangle_area(summed, t, cells);
    draw_triangle_area_over(over, t, cells);
  }
  // Wherever the coverages add up to 1, over gives 1 - (1 - c1)(1 - c2)... >= 1 - e^-(c1 + c2 ...).
  const double bound = 1 - std::exp(-1.0);
  int full = 0;
  for (int y = 0; y < 17; ++y) {
    for (int x = 0; x < 17; ++x) {
      if (std::abs(summed.at(x, y) - 1) > 1e-5) continue;
      ++full;
      INFO("pixel " << x << ", " << y);
      CHECK(over.at(x, y) >= bound - 1e-5);
    }
  }
  CHECK(full > 50);
  // At the centre, 256 small parts: close to the bound, far below the 0.75 of two halves.
  CHECK(over.at(8, 8) < 0.64);
}

}  // namespace tri::ch09
