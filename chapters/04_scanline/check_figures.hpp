/// @file
/// Chapter 04's comparison figures: where the two-loop, single-loop and published single-loop
/// fills differ, and the pixels the int casts add, as SVG diagrams.
#pragma once

#include "common/figures.hpp"

namespace tri::ch04::figures {

/// The green triangle zoomed, every pixel where the loop variants differ marked.
SvgFigure loop_differences();
/// The red and white triangles whole, the same differences as dots.
SvgFigure loop_differences_red_white();
/// The red triangle's lower-left corner: the truncated boundary A against the ideal edge.
SvgFigure truncation_close_up();

}  // namespace tri::ch04::figures
