/// @file
/// The triangle algorithms chapter 05 registers (DESIGN section 5).
#pragma once

#include <span>

#include "triangle_algorithm.hpp"

namespace tri::ch05 {

/// Every triangle algorithm of this chapter, in the order the chapter tells them: only
/// `edge_function` (the published-bug variant is never registered).
std::span<const TriangleAlgorithm> triangle_algorithms();

/// The registered entry of `edge_function`: rounds each vertex with nearest_pixel(), then
/// fill_triangle_edge_function().
void draw_edge_function(Canvas& canvas, const Triangle& triangle, Color color);

}  // namespace tri::ch05
