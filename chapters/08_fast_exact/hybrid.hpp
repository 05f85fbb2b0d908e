/// @file
/// Step 6 · choosing per triangle: step 5's eight-lane test for triangles within one block, step
/// 3's spans for everything larger; the best serial variant, and what each thread of step 7 runs.
#pragma once

#include <span>

#include "chapters/08_fast_exact/pixel_writers.hpp"
#include "chapters/08_fast_exact/triangle_setup.hpp"
#include "common/canvas.hpp"
#include "common/color.hpp"
#include "common/scene.hpp"
#include "common/triangle_algorithm.hpp"

namespace tri::ch08 {

/// Draws a prepared triangle: fill_simd when it fits one block (fits_one_block), else
/// fill_spans.
template <PixelWriter Writer>
void fill_hybrid(const TriangleSetup& setup, Writer& writer);
extern template void fill_hybrid(const TriangleSetup&, RowWriter&);
extern template void fill_hybrid(const TriangleSetup&, CountingWriter&);

/// Step 6 · one triangle: setup, then fill_hybrid.
void draw_triangle_hybrid(Canvas& canvas, const Triangle& triangle, Color color);
/// The same restricted to rows first_row..last_row (the registry's draw_rows entry).
void draw_triangle_hybrid_rows(Canvas& canvas, const Triangle& triangle, Color color, int first_row,
                               int last_row);

/// Step 6 · a whole batch on the calling thread: draw_triangle_hybrid for each triangle in order,
/// with the writer chosen once instead of per triangle.
void draw_batch_hybrid(Canvas& canvas, std::span<const SceneTriangle> triangles);

}  // namespace tri::ch08
