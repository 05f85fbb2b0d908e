#include "chapters/09_anti_aliasing/area_algorithms.hpp"

#include <algorithm>
#include <array>
#include <vector>

#include "chapters/09_anti_aliasing/area_cells.hpp"
#include "chapters/09_anti_aliasing/sample_spans.hpp"
#include "chapters/09_anti_aliasing/sampling.hpp"

namespace tri::ch09 {
namespace {

// The row cells live for one batch, so a scene allocates them once, not per triangle.
template <Blend blend>
void draw_area_cells(CoverageCanvas& canvas, std::span<const SceneTriangle> triangles) {
  RowCells cells;
  for (const SceneTriangle& t : triangles) draw_triangle_area(canvas, t.vertices, cells, blend);
}

// The pattern (regular_grid(n) or standard_pattern(n)) is built once per batch (one small
// allocation), then walked per triangle.
template <SamplePattern (*pattern_of)(int), int n>
void draw_samples(CoverageCanvas& canvas, std::span<const SceneTriangle> triangles) {
  const SamplePattern pattern = pattern_of(n);
  for (const SceneTriangle& t : triangles) draw_triangle_samples(canvas, t.vertices, pattern);
}

template <SamplePattern (*pattern_of)(int), int n>
void draw_samples_rows(CoverageCanvas& canvas, const Triangle& triangle, int first_row,
                       int last_row) {
  draw_triangle_samples_rows(canvas, triangle, pattern_of(n), first_row, last_row);
}

// The pattern of draw_samples<pattern_of, n>, for the registry.
template <SamplePattern (*pattern_of)(int), int n>
SamplePattern pattern() {
  return pattern_of(n);
}

constexpr std::string_view chapter = "09_anti_aliasing";

// A sampling entry: the pattern and its size decide how it draws, its rows and its samples.
template <SamplePattern (*pattern_of)(int), int n>
constexpr AreaAlgorithm sampling(std::string_view name, std::string_view summary, int samples) {
  return {.name = name,
          .chapter = chapter,
          .summary = summary,
          .draw = draw_samples<pattern_of, n>,
          .samples = samples,
          .draw_rows = draw_samples_rows<pattern_of, n>,
          .sample_pattern = pattern<pattern_of, n>};
}

// n x n regular samples per pixel.
template <int n>
constexpr AreaAlgorithm grid(std::string_view name, std::string_view summary) {
  return sampling<regular_grid, n>(name, summary, n * n);
}

// Vulkan's standard n-sample pattern.
template <int n>
constexpr AreaAlgorithm standard(std::string_view name, std::string_view summary) {
  return sampling<standard_pattern, n>(name, summary, n);
}

constexpr std::array algorithms = {
    AreaAlgorithm{.name = "area_cells",
                  .chapter = chapter,
                  .summary = "exact area: edges deposit area and cover into cells, summed per row",
                  .draw = draw_area_cells<Blend::sum>},
    AreaAlgorithm{.name = "area_cells_over",
                  .chapter = chapter,
                  .summary = "exact area per triangle, composited over as alpha (seams on meshes)",
                  .draw = draw_area_cells<Blend::over>,
                  .composites_over = true},
    grid<1>("samples_grid_1x1",
            "1 sample per pixel (the centre), top-left rule: inside or outside"),
    grid<2>("samples_grid_2x2", "2x2 regular samples per pixel, each by chapter 08's span walker"),
    grid<4>("samples_grid_4x4", "4x4 regular samples per pixel, each by chapter 08's span walker"),
    grid<8>("samples_grid_8x8", "8x8 regular samples per pixel, each by chapter 08's span walker"),
    grid<16>("samples_grid_16x16",
             "16x16 regular samples per pixel, each by chapter 08's span walker"),
    standard<2>("samples_standard_2",
                "Vulkan's standard 2-sample pattern, each by chapter 08's span walker"),
    standard<4>("samples_standard_4",
                "Vulkan's standard 4-sample pattern, each by chapter 08's span walker"),
    standard<8>("samples_standard_8",
                "Vulkan's standard 8-sample pattern, each by chapter 08's span walker"),
    standard<16>("samples_standard_16",
                 "Vulkan's standard 16-sample pattern, each by chapter 08's span walker"),
};

}  // namespace

std::span<const AreaAlgorithm> area_algorithms() noexcept {
  return algorithms;
}

std::size_t draw_coverage(const AreaAlgorithm& algorithm, CoverageCanvas& canvas,
                          std::span<const SceneTriangle> triangles) {
  const auto valid = [](const SceneTriangle& t) {
    return validate_triangle(t.vertices) == DrawResult::drawn;
  };
  if (std::all_of(triangles.begin(), triangles.end(), valid)) {
    algorithm.draw(canvas, triangles);
    return 0;
  }
  std::vector<SceneTriangle> kept;
  std::copy_if(triangles.begin(), triangles.end(), std::back_inserter(kept), valid);
  algorithm.draw(canvas, kept);
  return triangles.size() - kept.size();
}

}  // namespace tri::ch09
