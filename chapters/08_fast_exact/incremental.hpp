/// @file
/// Steps 1 and 2 · the bounding-box loop of chapter 07 with edge values updated by additions
/// (step 1), and all three signs tested with one branch (step 2).
#pragma once

#include <cstdint>
#include <utility>

#include "chapters/08_fast_exact/triangle_setup.hpp"
#include "common/canvas.hpp"
#include "common/color.hpp"
#include "common/triangle_algorithm.hpp"

namespace tri::ch08 {

// [listing walk_incremental]
/// Visits every pixel of a rectangle within the setup's range, row by row from the bottom, with
/// the three edge values at that pixel: visit(x, y, w0, w1, w2). Each value is the one before
/// plus a step, one addition per edge and pixel instead of chapter 07's two multiplications.
template <class Visit>
void walk_incremental(const TriangleSetup& setup, const ch05::PixelBox& box, Visit&& visit) {
  const std::int64_t dx = box.min.x - setup.range.min.x, dy = box.min.y - setup.range.min.y;
  const auto& [e0, e1, e2] = setup.edges;
  std::int64_t row0 = e0.at(dx, dy), row1 = e1.at(dx, dy), row2 = e2.at(dx, dy);
  for (int y = box.min.y; y <= box.max.y; ++y) {
    std::int64_t w0 = row0, w1 = row1, w2 = row2;
    for (int x = box.min.x; x <= box.max.x; ++x) {
      visit(x, y, w0, w1, w2);
      w0 += e0.step_x;
      w1 += e1.step_x;
      w2 += e2.step_x;
    }
    row0 += e0.step_y;
    row1 += e1.step_y;
    row2 += e2.step_y;
  }
}
// [/listing]

/// walk_incremental over the setup's whole range: every candidate pixel of the triangle.
template <class Visit>
void walk_incremental(const TriangleSetup& setup, Visit&& visit) {
  walk_incremental(setup, setup.range, std::forward<Visit>(visit));
}

/// Step 1 · incremental edge functions: chapter 07's rasterizer (same snapping, same bias, same
/// candidate pixels) with walk_incremental, three comparisons per pixel.
void draw_triangle_incremental(Canvas& canvas, const Triangle& triangle, Color color);
/// The same restricted to rows first_row..last_row (the registry's draw_rows entry).
void draw_triangle_incremental_rows(Canvas& canvas, const Triangle& triangle, Color color,
                                    int first_row, int last_row);

// [listing inside_all_edges]
/// Step 2's test: all three values are >= 0 exactly when their bitwise OR is, because a two's
/// complement number is negative exactly when its sign bit is set, and the OR has the sign bit
/// set exactly when one of them has.
constexpr bool inside_all_edges(std::int64_t w0, std::int64_t w1, std::int64_t w2) noexcept {
  return (w0 | w1 | w2) >= 0;
}
// [/listing]

/// Step 2 · testing all three edges at once: step 1 with inside_all_edges, one branch per pixel.
void draw_triangle_all_edges(Canvas& canvas, const Triangle& triangle, Color color);
/// The same restricted to rows first_row..last_row (the registry's draw_rows entry).
void draw_triangle_all_edges_rows(Canvas& canvas, const Triangle& triangle, Color color,
                                  int first_row, int last_row);

}  // namespace tri::ch08
