/// @file
/// The triangle algorithms chapter 06 registers (@ref design_registry "docs/DESIGN.md section 5").
#pragma once

#include <span>

#include "common/triangle_algorithm.hpp"

namespace tri::ch06 {

/// Every triangle algorithm of this chapter, in the order the chapter tells them.
std::span<const TriangleAlgorithm> triangle_algorithms();

}  // namespace tri::ch06
