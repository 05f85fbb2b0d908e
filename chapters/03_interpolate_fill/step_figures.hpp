/// @file
/// Chapter 03's step diagrams: each step of DrawFilledTriangle on the hand triangle, as SVG.
#pragma once

#include "common/figures.hpp"

namespace tri::ch03::figures {

/// Step 1: the vertices as passed and as sort_by_y names them, with the rows y0, y1, y2.
SvgFigure step1_sorted();
/// Step 2: x01, x12 and x02, one exact x per row on each ideal edge, P1's row computed twice.
SvgFigure step2_edges();
/// Step 3: x012 with P1's copy removed, beside x01 + x12 with the copy kept (one row too high).
SvgFigure step3_concatenate();
/// Step 4: the middle row decides which array is x_left; each row's two ends and their columns.
SvgFigure step4_left_right();
/// Step 5: one span per row from the nearest column of x_left to that of x_right.
SvgFigure step5_spans();

}  // namespace tri::ch03::figures
