/// @file
/// What the figures of chapters 05 and 06 share: tinyrenderer's three triangles as the chapter's
/// fill paints them, with the ideal edges on top and each triangle's pixel count in the legend, and
/// the labels A, B, C on a triangle's vertices.
#pragma once

#include <array>
#include <functional>
#include <string>

#include <glm/vec2.hpp>

#include "common/canvas.hpp"
#include "common/color.hpp"
#include "common/pixel_diagram.hpp"

namespace tri::ch02 {

/// A chapter's fill of one triangle with whole-pixel vertices: canvas, vertices, colour.
using WholePixelFill = std::function<void(Canvas&, glm::ivec2, glm::ivec2, glm::ivec2, Color)>;

/// The figures' colours for tinyrenderer's triangles (its white would vanish on the diagrams'
/// light background), and the names the legends give them.
inline constexpr std::array<Color, 3> tinyrenderer_figure_colors{
    diagram_colors::vermillion, diagram_colors::blue, diagram_colors::bluish_green};
inline constexpr std::array<const char*, 3> tinyrenderer_names{"first", "second", "third"};

/// A whole 200x200 scene at 3 units per pixel, without centre dots.
PixelDiagram tinyrenderer_scene_diagram(const std::string& title);

/// tinyrenderer's three triangles filled by `fill` in the figure colours, their ideal edges in
/// black, each in the legend with its vertices and the number of pixels it painted.
PixelDiagram tinyrenderer_fill_diagram(const std::string& title, const WholePixelFill& fill);

/// The vertices of the triangle v as dots labelled "A (x, y)", "B (x, y)" and "C (x, y)", each
/// label at its own place.
void label_vertices(PixelDiagram& d, const std::array<glm::ivec2, 3>& v,
                    const std::array<LabelPlace, 3>& places);

}  // namespace tri::ch02
