/// @file
/// How far a coverage algorithm (rule `area`) is from the exact area of chapter 09's oracle, per
/// triangle and for the composed scene (@ref design_error "docs/DESIGN.md section 6").
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "chapters/09_anti_aliasing/area_algorithms.hpp"
#include "chapters/09_anti_aliasing/coverage_canvas.hpp"
#include "common/scene.hpp"

namespace tri {

/// Adds the coverage of the triangles to the canvas, as an area algorithm does: the one thing the
/// error needs, so a rasterizer outside the registry (AGG, cairo, pixman) can be measured too.
using CoverageDraw =
    std::function<void(ch09::CoverageCanvas& canvas, std::span<const SceneTriangle> triangles)>;

/// The error of one coverage algorithm on one scene.
struct AreaErrorReport {
  std::uint64_t triangles = 0;  ///< triangles compared (refused ones are not)
  std::uint64_t rejected = 0;   ///< triangles refused: non-finite, out of range or off the grid
  /// Each triangle drawn alone: |coverage - exact area| over every (triangle, pixel) pair where
  /// either is above zero.
  std::uint64_t pixels = 0;
  double mean = 0;
  double rms = 0;
  double max = 0;
  int max_units = 0;  ///< the largest difference of the 16-bit values (round(65535 c))
  /// The whole scene drawn: the canvas against the exact coverages summed, both clamped to [0, 1],
  /// over the pixels where either is above zero. On a mesh this is the seam error.
  std::uint64_t composed_pixels = 0;
  double composed_mean = 0;
  double composed_max = 0;
  std::uint64_t composed_off_pixels = 0;  ///< pixels more than one 16-bit unit off
};

/// The exact coverages of a scene's triangles (chapter 09's oracle), computed once so that many
/// algorithms can be compared with them. Triangles the oracle cannot take exactly (off the 1/256
/// grid, beyond ±32768 pixels, non-finite) are left out and counted.
class AreaTruth {
 public:
  explicit AreaTruth(const Scene& scene);

  /// One triangle the oracle took: the pixels it can reach on the canvas (its bounding box and
  /// one pixel around), and its exact coverage of each, row by row from the region's bottom.
  struct TriangleTruth {
    int first_x, last_x, first_y, last_y;  ///< the region; empty when first > last
    std::vector<double> coverage;          ///< exact, as the nearest double
    std::vector<std::uint16_t> units;      ///< exact, as the 16-bit output (coverage_16)
  };

  int width() const noexcept { return width_; }
  int height() const noexcept { return height_; }
  /// The triangles the oracle took, in scene order, and their truths.
  const std::vector<SceneTriangle>& triangles() const noexcept { return triangles_; }
  const std::vector<TriangleTruth>& truths() const noexcept { return truths_; }
  /// The exact coverages of every triangle added up, per canvas pixel (row-major from the bottom).
  const std::vector<double>& summed() const noexcept { return summed_; }
  std::uint64_t rejected() const noexcept { return rejected_; }

 private:
  int width_, height_;
  std::vector<SceneTriangle> triangles_;
  std::vector<TriangleTruth> truths_;
  std::vector<double> summed_;
  std::uint64_t rejected_ = 0;
};

/// Measures a coverage drawing against the truth: each triangle drawn alone on an empty canvas,
/// then the whole scene.
AreaErrorReport measure_area_error(const CoverageDraw& draw, const AreaTruth& truth);

/// The same on a scene, computing its truth first.
AreaErrorReport measure_area_error(const CoverageDraw& draw, const Scene& scene);

/// The same for a registered coverage algorithm (drawn through ch09::draw_coverage).
AreaErrorReport measure_area_error(const ch09::AreaAlgorithm& algorithm, const Scene& scene);

/// How many pixels one draw of the triangles touches, each triangle's pixels counted on their own
/// (a pixel two triangles reach counts 2): the pixels of `raster --bench`'s rate for rule area.
std::uint64_t touched_pixels(const ch09::AreaAlgorithm& algorithm, int width, int height,
                             std::span<const SceneTriangle> triangles);

}  // namespace tri
