/// @file
/// What chapter 03's figures share: the hand triangle every step diagram is drawn on, short
/// numbers for labels, and which pixel centres lie in a triangle.
#pragma once

#include <array>
#include <string>

#include <glm/vec2.hpp>

#include "common/pixel_diagram.hpp"

namespace tri::ch03::figures {

/// The triangle of the step diagrams and most tests: small enough to check every value by hand.
inline constexpr std::array<glm::ivec2, 3> hand_triangle{{{1, 0}, {6, 3}, {2, 5}}};

/// A value as a label: at most two decimals, no trailing zeros ("2.67", "1.2", "6").
std::string short_number(double value);

/// True when the centre of `pixel` lies inside the triangle a b c or on its edges (exact, in
/// integers, either winding).
bool centre_in_triangle(glm::ivec2 a, glm::ivec2 b, glm::ivec2 c, glm::ivec2 pixel) noexcept;

/// For the edge a b (a.x != b.x) drawn as y = f(x): when the exact y at column x lies exactly
/// halfway between two pixel centres (a tie), sets `pixel` to the one rounding halves up picks,
/// (x, y + 1/2), and returns true; otherwise returns false.
bool halfway_tie(glm::ivec2 a, glm::ivec2 b, int x, glm::ivec2& pixel) noexcept;

/// A zoomed grid around the hand triangle with its ideal edges (unless `edges` is false) and
/// its sorted vertices labelled P0, P1, P2 with their coordinates.
PixelDiagram hand_diagram(std::string title, bool edges = true);

}  // namespace tri::ch03::figures
