/// @file
/// What chapter 04's figures share: a step drawn into a counting canvas, which pixel centres lie
/// in a triangle, and a zoomed diagram of one of the article's triangles.
#pragma once

#include <functional>
#include <string>

#include <glm/vec2.hpp>

#include "chapters/02_wireframe/example_triangles.hpp"
#include "common/canvas.hpp"
#include "common/pixel_diagram.hpp"

namespace tri::ch04::figures {

/// A step of the chapter applied to three vertices on a canvas.
using Step = std::function<void(Canvas&, glm::ivec2, glm::ivec2, glm::ivec2)>;

/// The article's 200x200 image with the step drawn on the triangle, counting writes.
Canvas drawn_by(const Step& step, const ch02::TinyrendererTriangle& triangle);

/// True when the centre of `pixel` lies inside the triangle or on its edges (exact, integers).
bool centre_in_triangle(const ch02::TinyrendererTriangle& triangle, glm::ivec2 pixel) noexcept;

/// The triangle the step diagrams are drawn on: the article's green one, the smallest.
const ch02::TinyrendererTriangle& diagram_triangle() noexcept;

/// A zoomed grid cropped to the green triangle, with its ideal edges and its vertices labelled
/// t0, t1, t2 (sorted by y) with their coordinates.
PixelDiagram green_diagram(std::string title);

}  // namespace tri::ch04::figures
