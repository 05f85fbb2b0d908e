/// @file
/// The example triangles the chapters draw from here on: tinyrenderer lesson 2's three test
/// triangles and Gambetta's Figure 7-1, each defined once.
#pragma once

#include <array>

#include <glm/vec2.hpp>

#include "common/color.hpp"

namespace tri::ch02 {

/// Side of tinyrenderer's square test image.
inline constexpr int tinyrenderer_image_size = 200;

/// One of tinyrenderer's test triangles: its vertices in the order the article passes them, and
/// the colour it draws it in.
struct TinyrendererTriangle {
  std::array<glm::ivec2, 3> vertices;
  Color color;
};

// [listing tinyrenderer_triangles]
/// Red, white and green, as tinyrenderer draws them.
inline constexpr std::array<TinyrendererTriangle, 3> tinyrenderer_triangles{{
    {{{{10, 70}, {50, 160}, {70, 80}}}, colors::red},
    {{{{180, 50}, {150, 1}, {70, 180}}}, colors::white},
    {{{{180, 150}, {120, 160}, {130, 180}}}, colors::green},
}};
// [/listing]

/// Side of the square canvas of Gambetta's Figure 7-1.
inline constexpr int figure_7_1_canvas_size = 600;

/// The vertices of Gambetta's Figure 7-1 (and 7-3) in his centred coordinates: origin in the
/// middle of the canvas, y up (tri::CenteredView maps them to canvas pixels).
inline constexpr std::array<glm::ivec2, 3> figure_7_1_triangle{
    {{-200, -250}, {200, 50}, {20, 250}}};

}  // namespace tri::ch02
