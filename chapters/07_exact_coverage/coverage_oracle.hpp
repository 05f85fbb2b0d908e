/// @file
/// The truth every rasterizer of the book is measured against
/// (@ref design_error "docs/DESIGN.md section 6"): pixel (i, j) belongs to triangle abc exactly
/// when the point (i, j) lies inside it, with the top-left rule deciding points exactly on an edge.
#pragma once

#include <glm/vec2.hpp>

#include "common/canvas.hpp"
#include "common/color.hpp"
#include "common/triangle_algorithm.hpp"

namespace tri::ch07 {

/// True for a *top* or *left* edge a -> b of a counter-clockwise triangle (y up): a top edge is
/// exactly horizontal with the triangle below it (it runs right to left), a left edge is not
/// horizontal and has the triangle to its right (it runs downwards).
bool is_top_left_edge(glm::dvec2 a, glm::dvec2 b) noexcept;

/// The triangle's vertices in counter-clockwise order (y up); the order given when the signed
/// area is already positive or zero.
Triangle counter_clockwise(const Triangle& triangle) noexcept;

/// Whether the centre of pixel p belongs to the triangle: strictly inside all three edges, or
/// exactly on edges that are all top or left. Zero-area triangles cover nothing; both windings
/// cover the same pixels. Exact for any finite vertices.
bool oracle_covers(const Triangle& triangle, glm::ivec2 p) noexcept;

/// Paints every covered pixel of the canvas, testing each pixel of the bounding box on its own
/// with exact arithmetic (never incrementally). Slow, and right.
void draw_triangle_oracle(Canvas& canvas, const Triangle& triangle, Color color);

/// The same restricted to rows first_row..last_row (the registry's draw_rows entry).
void draw_triangle_oracle_rows(Canvas& canvas, const Triangle& triangle, Color color, int first_row,
                               int last_row);

}  // namespace tri::ch07
