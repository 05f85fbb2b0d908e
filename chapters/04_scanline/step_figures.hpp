/// @file
/// Chapter 04's step diagrams: each step of the article's scanline fill on its green triangle.
#pragma once

#include "common/figures.hpp"

namespace tri::ch04::figures {

/// Step 1: the Bresenham outline over the ideal edges.
SvgFigure outlines();
/// Step 2: the outline split into boundary A (t0 -> t2) and boundary B (t0 -> t1 -> t2).
SvgFigure sorted_boundaries();
/// Step 3: only the two boundary points of each lower-half row, with the gaps hatched.
SvgFigure lower_half_points();
/// Step 4: the lower half filled, with the centres inside that the +1 leaves out.
SvgFigure lower_half_filled();
/// Step 5: both halves with two loops, row t1.y drawn twice.
SvgFigure two_loops();
/// Step 6: the single loop with second_half, the top row included.
SvgFigure single_loop();

}  // namespace tri::ch04::figures
