/// @file
/// Chapter 11: the learner's own fill, one function in one file (your_fill.cpp), graded by the
/// conformance suite outside the book's registry, so an unwritten template never breaks the
/// book's own tests.
#pragma once

#include "common/canvas.hpp"
#include "common/color.hpp"
#include "common/triangle_algorithm.hpp"

namespace tri::ch11 {

/// Your rasterizer: put_pixel(x, y, color) for every pixel (x, y) of the canvas whose centre, the
/// point (x, y) itself, lies inside the triangle; a centre exactly on an edge by the top-left rule
/// of chapter 07. The suite calls it once per triangle, with finite vertices within ±2^30.
void your_fill(Canvas& canvas, const Triangle& triangle, Color color);

}  // namespace tri::ch11
