/// @file
/// The pixel diagram of a failing case: the pixels the rule expects, the scene's triangle edges,
/// and every wrong pixel marked (tri::PixelDiagram).
#pragma once

#include <string>

#include "chapters/11_your_rasterizer/grading.hpp"

namespace tri::conformance {

/// The largest side, in pixels, a failure diagram shows; a larger failure shows the part around
/// its first wrong pixel.
inline constexpr int max_diagram_side = 40;

/// The case's wrong pixels as an SVG document: expected pixels filled, missed ones crossed in
/// vermillion, extra ones crossed in purple, those written twice or more hatched. Deterministic.
std::string failure_diagram_svg(const WrongCase& wrong, const std::string& title);

}  // namespace tri::conformance
