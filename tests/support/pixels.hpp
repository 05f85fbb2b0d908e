/// @file
/// Helpers the tests share: pixel sets read back from a canvas, and a portable random generator.
#pragma once

#include <cstdint>
#include <set>
#include <utility>

#include <glm/vec2.hpp>

#include "common/canvas.hpp"
#include "common/random.hpp"

namespace tri::testing {

/// A set of pixels as (x, y) pairs; ordered, so Catch prints it readably and sets compare.
using PixelSet = std::set<std::pair<int, int>>;

/// Every pixel written at least once (the canvas must count writes).
PixelSet written_pixels(const Canvas& canvas);

/// Pixels written more than once (the canvas must count writes).
PixelSet overdrawn_pixels(const Canvas& canvas);

/// The pixel centres inside or on the edges of the triangle abc (integer vertices, either
/// winding), clipped to a width x height canvas: exact, brute force, with 64-bit cross products.
/// What an `inclusive` algorithm must draw for a triangle of non-zero area; empty for zero area.
PixelSet inclusive_pixels(glm::ivec2 a, glm::ivec2 b, glm::ivec2 c, int width, int height);

/// The portable seeded generator, under the name the tests use.
using Random = tri::Random;

}  // namespace tri::testing
