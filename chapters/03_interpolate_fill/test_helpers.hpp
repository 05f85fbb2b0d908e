/// @file
/// What chapter 03's tests share: the hand triangle, pixel sets of a fill and of the book's
/// unclipped composition.
#pragma once

#include <array>
#include <cstdint>
#include <utility>

#include "chapters/03_interpolate_fill/diagram_support.hpp"
#include "chapters/03_interpolate_fill/fill_steps.hpp"
#include "chapters/03_interpolate_fill/filled_triangle.hpp"
#include "tests/support/pixels.hpp"

namespace tri::ch03::testing {

using figures::hand_triangle;
using tri::testing::minus;
using tri::testing::PixelSet;
using tri::testing::random_vertices;
using Vertices = std::array<glm::ivec2, 3>;

/// The pixels draw_filled_triangle writes on a counting width x height canvas.
inline PixelSet fill_pixels(const Vertices& v, int width, int height) {
  return tri::testing::pixels_drawn(width, height, [&](Canvas& canvas) {
    draw_filled_triangle(canvas, v[0], v[1], v[2], colors::white);
  });
}

/// Steps 2-5 on every row of the triangle, as the book runs them (no clipping before step 2).
inline PixelSet book_fill_pixels(const Vertices& v, int width, int height) {
  Canvas canvas(width, height);
  canvas.enable_write_counts();
  const SortedTriangle t = sort_by_y(v[0], v[1], v[2]);
  EdgeXs edges = interpolate_edges(t, triangle_rows(t));
  auto x012 = concatenate_short_sides(std::move(edges.x01), edges.x12);
  draw_spans(canvas, t.p0.y, choose_left_right(std::move(edges.x02), std::move(x012)),
             colors::white);
  return tri::testing::written_pixels(canvas);
}

/// How many pixels are in exactly one of the two sets.
inline int differing_pixels(const PixelSet& a, const PixelSet& b) {
  return static_cast<int>(tri::testing::symmetric_difference(a, b).size());
}

/// Twice the signed area, in 64 bits; zero for collinear vertices.
inline std::int64_t doubled_area(const Vertices& v) {
  return tri::testing::doubled_area(v[0], v[1], v[2]);
}

}  // namespace tri::ch03::testing
