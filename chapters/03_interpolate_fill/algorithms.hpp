/// @file
/// The triangle algorithms chapter 03 registers (@ref design_registry "docs/DESIGN.md section 5").
#pragma once

#include <span>

#include "common/triangle_algorithm.hpp"

namespace tri::ch03 {

/// Every triangle algorithm of this chapter, in the order the chapter tells them: one,
/// `gambetta_interpolate_fill` (draw_filled_triangle on the vertices rounded with
/// tri::nearest_pixel), registered as CoverageRule::approximate.
std::span<const TriangleAlgorithm> triangle_algorithms();

}  // namespace tri::ch03
