/// @file
/// Step 2 of the edge-function fill: the 2-D cross product, and the three values it gives for a
/// point P against the edges AB, BC and CA (the article's AB x AP, BC x BP, CA x CP).
#pragma once

#include <cstdint>

#include <glm/ext/vector_int2_sized.hpp>
#include <glm/ext/vector_int3_sized.hpp>
#include <glm/vec2.hpp>

namespace tri::ch05 {

// [listing cross_2d]
/// The z component of the 3-D cross product of (u, 0) and (v, 0): u.x v.y - u.y v.x. With y up it
/// is > 0 when v points to the left of u (counter-clockwise from it), < 0 to the right, 0 when
/// they are parallel. It is also twice the signed area of the triangle spanned by u and v.
/// Exact as long as |u.x v.y - u.y v.x| and both products fit in 63 bits (see edge_cross()).
constexpr std::int64_t cross_2d(glm::i64vec2 u, glm::i64vec2 v) noexcept {
  return u.x * v.y - u.y * v.x;
}
// [/listing]

/// AB x AP: > 0 when p is left of the directed edge a -> b, 0 on its line, < 0 right of it.
/// Computed exactly in 64 bits for any a, b, p within ±2^30: every difference (up to 2^31) is
/// taken in 64 bits, and the result is twice the area of a triangle inside a square of side
/// 2^31, so at most 2^62 in magnitude, as is each of the two products.
std::int64_t edge_cross(glm::ivec2 a, glm::ivec2 b, glm::ivec2 p) noexcept;

/// The three edge values of p against triangle abc: (AB x AP, BC x BP, CA x CP). Their sum is
/// AB x AC, twice the triangle's signed area, whatever p is.
glm::i64vec3 edge_crosses(glm::ivec2 a, glm::ivec2 b, glm::ivec2 c, glm::ivec2 p) noexcept;

/// The published version of edge_crosses(), kept only to show its bug (never registered): BP and
/// CP take their y from A instead of from B and C. That moves line BC vertically by a.y - b.y
/// and line CA by a.y - c.y, i.e. it adds BC.x (b.y - a.y) and CA.x (c.y - a.y) to the second and
/// third values. Invisible only when both terms vanish, e.g. AB horizontal and CA vertical.
/// Exact for vertices within ±2^30 and p a canvas pixel (0 <= p.x, p.y < 16384): each product
/// then stays below 2^61 + 2^45, their difference below 2^63.
glm::i64vec3 edge_crosses_published_bug(glm::ivec2 a, glm::ivec2 b, glm::ivec2 c,
                                        glm::ivec2 p) noexcept;

}  // namespace tri::ch05
