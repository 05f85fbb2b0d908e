/// @file
/// Coverage by counting samples: N x N regular points per pixel, or the rotated patterns GPUs
/// use, each point decided by chapter 07's exact top-left rule.
#pragma once

#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "common/triangle_algorithm.hpp"

namespace tri::ch09 {

/// Sample offsets are whole multiples of 1/32 pixel: fine enough for every pattern here, coarse
/// enough that scaling a 1/256-grid triangle by 32 stays exact in doubles.
inline constexpr int sample_units = 32;

/// Where a pixel's samples lie, as offsets from its centre in 1/32 pixel (x right, y up).
struct SamplePattern {
  std::string name;                 ///< e.g. "grid_4x4", "standard_16"
  std::vector<glm::ivec2> offsets;  ///< one per sample, each within [-16, 16)
};

/// Step 2 · n x n samples on a regular grid: sample (k, l) at (k + 1/2) / n across the pixel.
/// n must divide 16 (1, 2, 4, 8 or 16; throws std::invalid_argument otherwise).
SamplePattern regular_grid(int n);

/// Step 3 · Vulkan's standard sample locations for `count` samples (2, 4, 8 or 16): rotated,
/// so no two samples share a row or a column.
SamplePattern standard_pattern(int count);

/// The fraction of the pattern's samples inside the triangle, each decided exactly with the
/// top-left rule (chapter 07's oracle at the sample grid). The triangle's vertices must lie on
/// the 1/256 grid within ±2^15 pixels.
double sampled_coverage(const Triangle& triangle, glm::ivec2 pixel, const SamplePattern& pattern);

/// The same fraction for a triangle anywhere within ±2^30, its vertices first snapped to the
/// 1/256 grid as chapter 08 snaps them: the value draw_triangle_samples gives, for any input.
double snapped_sampled_coverage(const Triangle& triangle, glm::ivec2 pixel,
                                const SamplePattern& pattern);

}  // namespace tri::ch09
