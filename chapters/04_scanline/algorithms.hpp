/// @file
/// The triangle algorithms chapter 04 registers (@ref design_registry "docs/DESIGN.md section 5"):
/// the article's two-loop fill (step 5) and its single-loop fill (step 6, with the top row).
#pragma once

#include <span>

#include "common/triangle_algorithm.hpp"

namespace tri::ch04 {

/// Every triangle algorithm of this chapter, in the order the chapter tells them.
std::span<const TriangleAlgorithm> triangle_algorithms();

}  // namespace tri::ch04
