/// @file
/// The registry: every triangle algorithm of the book, in chapter order
/// (@ref design_registry "docs/DESIGN.md section 5").
#pragma once

#include <string_view>
#include <vector>

#include "chapters/09_anti_aliasing/area_algorithms.hpp"
#include "common/triangle_algorithm.hpp"
#include "measure/drawable.hpp"

namespace tri {

/// Every registered drawable, in chapter order: the colour algorithms of chapters 03 to 08, then
/// chapter 09's coverage algorithms. `raster`, the tests and the fuzzers ask these descriptions.
std::vector<Drawable> registered_drawables();

/// All registered triangle algorithms, in chapter order. Tests and the benchmark iterate this, so
/// an algorithm is covered the moment its chapter lists it.
std::vector<TriangleAlgorithm> registered_algorithms();

/// All registered coverage algorithms (rule `area`), in chapter order: they draw onto a coverage
/// canvas, not a colour one, so they are listed apart from the triangle algorithms.
std::vector<ch09::AreaAlgorithm> registered_area_algorithms();

}  // namespace tri
