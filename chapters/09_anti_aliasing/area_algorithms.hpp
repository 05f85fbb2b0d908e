/// @file
/// Chapter 09's algorithms as the registry lists them: each adds a batch of triangles' coverage
/// to a coverage canvas, under the rule `area` (the value is a fraction of the pixel).
#pragma once

#include <cstddef>
#include <span>
#include <string_view>

#include "chapters/09_anti_aliasing/coverage_canvas.hpp"
#include "chapters/09_anti_aliasing/sampling.hpp"
#include "common/scene.hpp"
#include "common/triangle_algorithm.hpp"

namespace tri::ch09 {

/// Adds the coverage of every triangle, in order, to the canvas (colours are ignored). Called
/// only with triangles that passed validate_triangle.
using DrawCoverageFunction = void (*)(CoverageCanvas& canvas,
                                      std::span<const SceneTriangle> triangles);

/// Adds one triangle's coverage to the pixels of rows first_row..last_row only, exactly what
/// DrawCoverageFunction adds there, so a huge triangle's work can be split into bands of rows.
using DrawCoverageRowsFunction = void (*)(CoverageCanvas& canvas, const Triangle& triangle,
                                          int first_row, int last_row);

/// A registered coverage algorithm.
struct AreaAlgorithm {
  std::string_view name;     ///< stable name, e.g. "area_cells"
  std::string_view chapter;  ///< "09_anti_aliasing"
  CoverageRule rule = CoverageRule::area;
  std::string_view summary;  ///< one line for `raster --list`
  DrawCoverageFunction draw;
  int samples = 0;  ///< samples per pixel; 0 for an algorithm that computes the area itself
  DrawCoverageRowsFunction draw_rows = nullptr;  ///< optional: the draw restricted to rows
  /// The pattern a sampling algorithm counts (its samples' fraction inside the triangle is its
  /// exact answer: snapped_sampled_coverage); null for an algorithm that computes the area.
  SamplePattern (*sample_pattern)() = nullptr;
  /// Composites each triangle "over" the canvas as alpha (c + a(1 - c)) instead of adding it.
  bool composites_over = false;
};

/// Chapter 09's algorithms: the exact area by cells (summed, and composited "over" as a 2-D
/// library does), and the sample counts of steps 2 and 3 (grids of 1 to 256 samples, Vulkan's
/// standard 2 to 16).
std::span<const AreaAlgorithm> area_algorithms() noexcept;

/// Validates every triangle, then lets the algorithm add the valid ones' coverage. Returns how
/// many were refused (they add nothing).
std::size_t draw_coverage(const AreaAlgorithm& algorithm, CoverageCanvas& canvas,
                          std::span<const SceneTriangle> triangles);

}  // namespace tri::ch09
