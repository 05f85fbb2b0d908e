/// @file
/// The properties fuzz_rasterizers checks on every input; the regression tests apply the same
/// checks to the seed corpus and to past findings with the normal compiler.
#pragma once

#include <string>
#include <vector>

#include "common/triangle_algorithm.hpp"
#include "fuzz/rasterizer_input.hpp"

namespace tri::fuzz {

/// The promises an input broke, one line each; empty when every check held.
using Findings = std::vector<std::string>;

/// True when all six coordinates are multiples of 1/256 within ±2^30: the grid on which an
/// algorithm whose rule is top-left must cover exactly the oracle's pixels.
bool on_subpixel_grid(const Triangle& triangle) noexcept;

/// The triangle as a scene line, "tri x0 y0 x1 y1 x2 y2 r g b", with every digit a double needs,
/// so a finding can be pasted into a scene or a test.
std::string scene_line(const SceneTriangle& triangle);

/// Draws each triangle of the input on its own fresh canvas (write counts on, a background unlike
/// the triangle's colour) through draw_triangle, and checks:
///  - nothing is written outside the canvas (outside_writes() == 0);
///  - a triangle validate_triangle refuses leaves every pixel and every count untouched;
///  - every pixel written holds the triangle's colour, every other pixel the background;
///  - an algorithm whose rule is top-left covers exactly the oracle's pixels when the vertices lie
///    on the 1/256 grid.
/// For algorithms with a batch entry point (draw_batch, make_renderer) or threads, it also draws
/// all triangles at once with draw_triangles and checks that the picture equals drawing them one
/// by one, that nothing is written outside, and that the same number of triangles is refused.
Findings check_rasterizer(const TriangleAlgorithm& algorithm, const RasterizerInput& input);

}  // namespace tri::fuzz
