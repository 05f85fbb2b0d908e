/// @file
/// The triangle algorithms chapter 05 registers (@ref design_registry "docs/DESIGN.md section 5").
#pragma once

#include <span>

#include "common/triangle_algorithm.hpp"

namespace tri::ch05 {

/// Every triangle algorithm of this chapter, in the order the chapter tells them: only
/// `edge_function` (the published-bug variant is never registered).
std::span<const TriangleAlgorithm> triangle_algorithms();

}  // namespace tri::ch05
