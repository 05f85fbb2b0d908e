/// @file
/// Steps 2 and 3, fast: the same samples as sampled_coverage, found for a whole triangle by
/// chapter 08's exact span walker, once per sample position.
#pragma once

#include "chapters/09_anti_aliasing/coverage_canvas.hpp"
#include "chapters/09_anti_aliasing/sampling.hpp"
#include "common/triangle_algorithm.hpp"

namespace tri::ch09 {

/// Adds to every pixel the fraction of the pattern's samples inside the triangle, the same value
/// sampled_coverage gives. Sample centre + o is inside the triangle exactly when the centre is
/// inside the triangle moved by -o, so each offset is one pass of chapter 08's span walker over
/// the moved triangle, adding 1 / samples to every pixel of each span. Like chapter 08, vertices
/// are snapped to the 1/256 grid first; the offsets (multiples of 1/32) keep them on it.
void draw_triangle_samples(CoverageCanvas& canvas, const Triangle& triangle,
                           const SamplePattern& pattern);

/// The same restricted to rows first_row..last_row: each pass's setup clipped to them, so each
/// pixel of those rows gets the same additions in the same order.
void draw_triangle_samples_rows(CoverageCanvas& canvas, const Triangle& triangle,
                                const SamplePattern& pattern, int first_row, int last_row);

}  // namespace tri::ch09
