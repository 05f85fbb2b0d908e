/// @file
/// The chapter's exercises: each function here has a reference solution in exercises.cpp and a
/// test in exercises_test.cpp. Replace a body with your own and run the chapter's tests.
#pragma once

#include <span>
#include <vector>

#include <glm/vec2.hpp>

#include "chapters/09_anti_aliasing/fraction.hpp"
#include "chapters/09_anti_aliasing/sampling.hpp"
#include "common/triangle_algorithm.hpp"

namespace tri::ch09::exercises {

/// Exercise 1 · coverages c1, c2, ... composited over an empty pixel one after another, each as
/// v + c (1 - v) (step 5): the value the pixel ends with.
double composite_over(std::span<const double> coverages);

/// Exercise 2 · the sRGB encoding of a linear intensity in [0, 1]: 12.92 x below 0.0031308,
/// 1.055 x^(1/2.4) - 0.055 above (IEC 61966-2-1).
double srgb_encode(double linear);

/// Exercise 3 · how much of a pixel a straight vertical edge covers under a tent filter of radius
/// 1 (weight 1 - |t| at distance t from the centre, across x) instead of the pixel's box: the
/// shape is everything left of x = centre + d.
double tent_filtered_edge(double d);

/// How overlapping shapes combine at a sample.
enum class FillRule {
  non_zero,  ///< inside where the winding number is not 0
  even_odd   ///< inside where the winding number is odd
};

/// Exercise 4 · the fraction of the pattern's samples inside the union of `shapes` under `rule`:
/// a counter-clockwise triangle (y up) winds +1 around the samples it covers, a clockwise one -1.
/// Vertices on the 1/256 grid, as sampled_coverage requires.
double fill_rule_coverage(std::span<const Triangle> shapes, glm::ivec2 pixel,
                          const SamplePattern& pattern, FillRule rule);

/// Exercise 5 · font-rs's accumulation buffer for pixel row `row`, columns 0 .. width - 1, of a
/// counter-clockwise triangle (y up) within those columns: each edge piece adds its area (its
/// height times its distance to the pixel's right side) to its own pixel and the rest of its
/// height to the next pixel; a running sum along the row then gives minus each pixel's coverage.
/// Returns the coverages. Use edge_in_pixel_row() for the pieces.
std::vector<Fraction> accumulated_row(const Triangle& triangle, int row, int width);

}  // namespace tri::ch09::exercises
