/// @file
/// The registry: every triangle algorithm of the book, in chapter order
/// (@ref design_registry "docs/DESIGN.md section 5").
#pragma once

#include <string_view>
#include <vector>

#include "common/triangle_algorithm.hpp"

namespace tri {

/// All registered triangle algorithms, in chapter order. Tests and the benchmark iterate this, so
/// an algorithm is covered the moment its chapter lists it.
std::vector<TriangleAlgorithm> registered_algorithms();

/// The algorithm with this name, or nullptr.
const TriangleAlgorithm* find_algorithm(const std::vector<TriangleAlgorithm>& algorithms,
                                        std::string_view name);

}  // namespace tri
