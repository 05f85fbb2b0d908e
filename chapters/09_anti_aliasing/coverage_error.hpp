/// @file
/// How far an estimate of coverage is from the exact area, over the pixels a triangle touches.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include <glm/vec2.hpp>

#include "common/triangle_algorithm.hpp"

namespace tri::ch09 {

/// Any way of estimating one pixel's coverage by one triangle.
using PixelCoverageFunction = std::function<double(const Triangle&, glm::ivec2 pixel)>;

/// |estimate - exact| over the pixels where either is above zero.
struct CoverageError {
  double mean = 0;         ///< the average absolute difference
  double rms = 0;          ///< the root of the mean squared difference
  double max = 0;          ///< the largest absolute difference
  std::size_t pixels = 0;  ///< how many pixels were compared
};

/// The one area-error metric of the book (this chapter's tests, the report and `raster` use it):
/// |estimate - exact| summed over the pixels where either is above zero.
class AreaDifferences {
 public:
  /// Counts one pixel unless both are zero; returns whether it counted.
  bool add(double estimate, double exact) noexcept;
  [[nodiscard]] CoverageError summary() const noexcept;

 private:
  double absolute_ = 0, squared_ = 0, max_ = 0;
  std::size_t pixels_ = 0;
};

/// Compares `estimate` with the exact coverage on every pixel of the triangle's bounding box
/// (plus one pixel around it), counting the pixels where either is above zero.
CoverageError coverage_error(const Triangle& triangle, const PixelCoverageFunction& estimate);

/// The same over several triangles, each pixel of each triangle counted once.
CoverageError coverage_error(const std::vector<Triangle>& triangles,
                             const PixelCoverageFunction& estimate);

}  // namespace tri::ch09
