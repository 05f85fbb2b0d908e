/// @file
/// The exact sign of the 2-D orientation determinant: the one question every coverage decision
/// asks ("is p left of, right of, or exactly on the line a -> b?"), answered without rounding.
#pragma once

#include <glm/vec2.hpp>

namespace tri::ch07 {

/// The sign of (b - a) x (p - a) = (b.x - a.x)(p.y - a.y) - (b.y - a.y)(p.x - a.x), exactly, for
/// any finite doubles: +1 when p is left of a -> b (counter-clockwise with y up), -1 when it is
/// right, 0 when the three points are exactly collinear.
///
/// Fast path: the determinant in doubles, trusted when it is farther from zero than Shewchuk's
/// error bound for this formula. Otherwise the exact path: the determinant expands into six
/// products of input coordinates, each an integer (the product of two 53-bit mantissas, at most
/// 106 bits) times a power of two, and they are summed exactly in a wide two's-complement integer.
int exact_orientation(glm::dvec2 a, glm::dvec2 b, glm::dvec2 p) noexcept;

/// The same question answered by the exact path only (for tests that compare the two paths).
int exact_orientation_slow_path(glm::dvec2 a, glm::dvec2 b, glm::dvec2 p) noexcept;

}  // namespace tri::ch07
