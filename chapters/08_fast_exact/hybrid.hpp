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

/// Step 6 · choosing per triangle: fill_simd when the prepared triangle fits one block
/// (fits_one_block), else fill_spans, through either canvas writer. With its canvas entries
/// (draw_triangle_hybrid for one triangle, OnCanvas' draw_rows for a band) in hybrid.cpp.
void fill_hybrid(const TriangleSetup& setup, CanvasWriter writer);
extern template struct OnCanvas<fill_hybrid>;
inline constexpr DrawTriangleFunction draw_triangle_hybrid = OnCanvas<fill_hybrid>::draw;

/// Step 6 · a whole batch on the calling thread: draw_triangle_hybrid for each triangle in order,
/// with the writer chosen once instead of per triangle.
void draw_batch_hybrid(Canvas& canvas, std::span<const SceneTriangle> triangles);

}  // namespace tri::ch08
