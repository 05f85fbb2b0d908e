/// @file
/// A drawn line next to the exact answer, step by step: the tool behind the chapter's figures,
/// which show where an algorithm leaves the nearest pixel (only ever at a tie).
#pragma once

#include <array>
#include <optional>
#include <vector>

#include <glm/vec2.hpp>

#include "chapters/01_lines/line_algorithms.hpp"
#include "chapters/01_lines/line_reference.hpp"

namespace tri::ch01 {

/// One step along the major axis of a line: the exact nearest pixel and the pixel drawn there.
struct LineStep {
  ExactLinePixel exact;  ///< nearest pixel (a tie rounded up) and whether the step is a tie
  glm::ivec2 drawn;      ///< the pixel the algorithm drew at this major coordinate
};

/// Draws from -> to with `draw` and pairs each step's drawn pixel with the exact pixel, ordered
/// like exact_line_pixels (from the smaller major coordinate). Coordinates must be in 0..4095,
/// since the line is drawn where it lies, on a canvas that holds it: moving a line can change
/// how a floating-point algorithm rounds its ties. Throws std::invalid_argument outside that
/// range and std::logic_error if the algorithm leaves a step empty.
std::vector<LineStep> steps_against_exact(DrawLineFunction draw, glm::ivec2 from, glm::ivec2 to);

/// A spoke of the chapter's star: a segment from the centre outwards.
using Segment = std::array<glm::ivec2, 2>;

/// The chapter's star: `count` spokes from `centre`, evenly spaced from angle 0 counterclockwise,
/// each ending at the pixel nearest to the point at distance `radius`.
std::vector<Segment> star_spokes(glm::ivec2 centre, int radius, int count);

}  // namespace tri::ch01
