/// @file
/// Gambetta's DrawWireframeTriangle: a triangle's outline as three lines.
#pragma once

#include <array>
#include <vector>

#include <glm/vec2.hpp>

#include "common/canvas.hpp"
#include "common/color.hpp"

namespace tri::ch02 {

/// Draws the edges p0-p1, p1-p2 and p2-p0 with chapter 01's tri::ch01::draw_line_gambetta.
/// Each line includes both its endpoints, so every vertex is written twice (once per edge that
/// meets there). The line draws the same pixels in both directions, so the outline does not
/// depend on the order of the vertices. As safe as that line function: every pixel of each edge
/// is visited, so vertices far outside the canvas cost time and count outside writes.
void draw_wireframe_triangle(Canvas& canvas, glm::ivec2 p0, glm::ivec2 p1, glm::ivec2 p2,
                             Color color);

/// The pixels that each edge of draw_wireframe_triangle's outline draws, so a figure can show
/// which edge drew what and where two edges meet: [0] is edge p0-p1, [1] p1-p2, [2] p2-p0, each
/// sorted by row, then column. Coordinates must be in 0..4095 (the edges are drawn where they
/// lie); throws std::invalid_argument otherwise.
std::array<std::vector<glm::ivec2>, 3> outline_edge_pixels(glm::ivec2 p0, glm::ivec2 p1,
                                                           glm::ivec2 p2);

}  // namespace tri::ch02
