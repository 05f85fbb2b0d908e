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

/// Compares `estimate` with the exact coverage on every pixel of the triangle's bounding box
/// (plus one pixel around it), counting the pixels where either is above zero.
CoverageError coverage_error(const Triangle& triangle, const PixelCoverageFunction& estimate);

/// The same over several triangles, each pixel of each triangle counted once.
CoverageError coverage_error(const std::vector<Triangle>& triangles,
                             const PixelCoverageFunction& estimate);

}  // namespace tri::ch09
