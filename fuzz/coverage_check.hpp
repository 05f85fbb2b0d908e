/// @file
/// The properties fuzz_coverage checks on every input: chapter 09's coverage algorithms against
/// the exact area (step 1's rational oracle) and against the exact count of their own samples.
/// The regression tests apply the same checks to the seed corpus and to past findings.
#pragma once

#include "chapters/09_anti_aliasing/area_algorithms.hpp"
#include "fuzz/rasterizer_check.hpp"
#include "fuzz/rasterizer_input.hpp"

namespace tri::fuzz {

/// The oracle computes every pixel in exact fractions: coverage inputs keep to 16 x 16 canvases,
/// so that one execution stays in the milliseconds.
inline constexpr int max_coverage_canvas_side = 16;

/// Vertices this close to the 1/256 grid are compared with the oracle on the grid triangle: their
/// exact coverage differs from it by less than 4 x the distance x (perimeter + 1).
inline constexpr double oracle_grid_distance = 0x1p-40;

/// The input with its canvas cut to at most 16 x 16: each side becomes (side - 1) mod 16 + 1.
RasterizerInput coverage_input(RasterizerInput input);

/// Draws each triangle alone through draw_coverage on a fresh canvas and checks:
///  - a triangle validate_triangle refuses is counted as refused and adds nothing;
///  - every value is finite and within [0, 1] (to 1e-6);
///  - an exact-area algorithm is within 1e-6 of the exact area where the oracle knows it: vertices
///    within oracle_grid_distance of the 1/256 grid and within ±2^15 (the tolerance grows by the
///    bound above);
///  - a sampling algorithm gives every pixel exactly snapped_sampled_coverage, the fraction of its
///    own samples inside the (snapped) triangle.
/// Then all triangles at once: summed, the picture is the sum of the triangles drawn alone (to
/// 1e-6 per triangle; exactly for samples), composited "over", their composition in order; the
/// same number of triangles is refused.
Findings check_coverage(const ch09::AreaAlgorithm& algorithm, const RasterizerInput& input);

}  // namespace tri::fuzz
