/// @file
/// The triangle algorithms chapter 07 registers (@ref design_registry "docs/DESIGN.md section 5").
#pragma once

#include <span>

#include "common/triangle_algorithm.hpp"

namespace tri::ch07 {

/// The exact oracle and the fixed-point rasterizer.
std::span<const TriangleAlgorithm> triangle_algorithms();

}  // namespace tri::ch07
