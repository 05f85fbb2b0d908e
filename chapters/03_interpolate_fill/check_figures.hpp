/// @file
/// Chapter 03's check figures: Figure 7-3 (the outline drawn over the fill), tinyrenderer's
/// triangles checked the same way, and the traps of the C++ port, as SVG.
#pragma once

#include "common/figures.hpp"

namespace tri::ch03::figures {

/// Figure 7-3 on its 600x600 canvas: fill, outline on top, outline pixels outside the fill.
/// flip = 1 is the book's triangle, flip = -1 the same triangle upside down.
SvgFigure figure_7_3(int flip);
/// The same stretch of the wide edge, zoomed, upright and flipped, with its halfway ties.
SvgFigure figure_7_3_close_up();
/// tinyrenderer's three triangles filled, their outlines on top, outline pixels outside marked.
SvgFigure tinyrenderer_fill_outline();
/// The green one of those triangles zoomed, each outline pixel outside the fill crossed.
SvgFigure tinyrenderer_fill_outline_close_up();
/// The hand triangle's fill with the pixels lost to `y < P2.y` and `x < x_right` marked.
SvgFigure trap_one_short();
/// The hand triangle's fill with and without removing P1's duplicate, the difference marked.
SvgFigure trap_no_pop_back();

}  // namespace tri::ch03::figures
