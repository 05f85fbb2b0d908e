/// @file
/// What chapter 04's figures share: a step drawn into a counting canvas and a zoomed diagram of
/// one of the article's triangles (which pixel centres lie in a triangle is chapter 03's
/// tri::ch03::figures::centre_in_triangle).
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

/// The triangle the step diagrams are drawn on: the article's green one, the smallest.
const ch02::TinyrendererTriangle& diagram_triangle() noexcept;

/// A zoomed grid cropped to the green triangle, with its ideal edges and its vertices labelled
/// t0, t1, t2 (sorted by y) with their coordinates.
PixelDiagram green_diagram(std::string title);

}  // namespace tri::ch04::figures
