/// @file
/// The chapter's four line algorithms side by side, so the figures and tests can loop over them.
#pragma once

#include <array>
#include <string_view>

#include "chapters/01_lines/lines.hpp"

namespace tri::ch01 {

/// Signature shared by the four line algorithms.
using DrawLineFunction = void (*)(Canvas&, glm::ivec2, glm::ivec2, Color);

/// A line algorithm and the promise it makes about direction.
struct LineAlgorithm {
  std::string_view name;
  DrawLineFunction draw;
  bool same_pixels_both_directions;  ///< p0 -> p1 and p1 -> p0 give identical pixels
};

/// Gambetta, DDA, Bresenham and midpoint, in the order the chapter tells them.
inline constexpr std::array<LineAlgorithm, 4> line_algorithms{{
    {"gambetta", draw_line_gambetta, true},
    {"dda", draw_line_dda, false},
    {"bresenham", draw_line_bresenham, true},
    {"midpoint", draw_line_midpoint, false},
}};

}  // namespace tri::ch01
