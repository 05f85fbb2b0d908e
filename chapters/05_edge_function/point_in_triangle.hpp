/// @file
/// Step 3 of the edge-function fill: is one pixel centre inside the triangle (edges included)?
#pragma once

#include <glm/ext/vector_int3_sized.hpp>
#include <glm/vec2.hpp>

namespace tri::ch05 {

/// True when the three edge values all have the same sign, zeros allowed: all >= 0 (p inside or
/// on the edges of a counter-clockwise triangle, y up) or all <= 0 (the same for a clockwise one).
/// For a triangle of non-zero area the values sum to twice its area, so they cannot all be
/// <= 0 when it is counter-clockwise (nor all >= 0 when clockwise): each winding is tested
/// exactly, with no need to know it. For a zero-area triangle they sum to 0, so the test holds
/// only where all three are 0: on the line through the vertices.
bool same_sign_or_zero(glm::i64vec3 edge_values) noexcept;

/// The per-pixel inside test: p lies inside triangle abc or on one of its edges, for either
/// winding (same_sign_or_zero() of edge_crosses()). Vertices within ±2^30, p too.
bool inside_triangle(glm::ivec2 a, glm::ivec2 b, glm::ivec2 c, glm::ivec2 p) noexcept;

/// The published inside test, kept only to show its bug (never registered): the same sign test
/// on edge_crosses_published_bug(), whose BP and CP read A's y. p must be a canvas pixel.
bool inside_triangle_published_bug(glm::ivec2 a, glm::ivec2 b, glm::ivec2 c, glm::ivec2 p) noexcept;

}  // namespace tri::ch05
