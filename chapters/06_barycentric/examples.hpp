/// @file
/// The triangles chapter 06 talks about, shared by its figures and its tests.
#pragma once

#include <array>

#include <glm/vec2.hpp>

namespace tri::ch06 {

/// Three integer vertices.
using PixelTriangle = std::array<glm::ivec2, 3>;

/// A small triangle whose 13 pixels the chapter checks by hand.
inline constexpr PixelTriangle hand_checked_triangle{{{1, 1}, {6, 2}, {3, 5}}};

/// The first triangle of a seeded search (float_vs_double_test.cpp) where float and double fill
/// different pixels of a 16x16 canvas. Vertices within ±10^4; the edge from the second to the
/// third vertex passes exactly through pixel (15, 11), its midpoint, which float misses.
inline constexpr PixelTriangle float_double_disagreement{
    {{6560, -9269}, {4156, 4248}, {-4126, -4226}}};

/// Three collinear vertices (direction (1, 7), through pixel (16, 16)) about 10^7 away: a
/// zero-area triangle whose area float computes as 2^21, so the guard lets it through.
inline constexpr PixelTriangle collinear_at_ten_million{
    {{-1428555, -9999981}, {1428588, 10000020}, {17, 23}}};

}  // namespace tri::ch06
