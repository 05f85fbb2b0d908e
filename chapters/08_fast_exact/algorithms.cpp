#include "chapters/08_fast_exact/algorithms.hpp"

#include <array>

#include "chapters/08_fast_exact/blocks.hpp"
#include "chapters/08_fast_exact/hybrid.hpp"
#include "chapters/08_fast_exact/incremental.hpp"
#include "chapters/08_fast_exact/simd.hpp"
#include "chapters/08_fast_exact/spans.hpp"
#include "chapters/08_fast_exact/threaded.hpp"

namespace tri::ch08 {

std::span<const TriangleAlgorithm> triangle_algorithms() {
  static constexpr std::array<TriangleAlgorithm, 7> algorithms{{
      {.name = "fast_incremental",
       .chapter = "08_fast_exact",
       .rule = CoverageRule::top_left,
       .summary = "fixed_point_8 with edge values updated by one addition per pixel and edge",
       .draw = draw_triangle_incremental},
      {.name = "fast_all_edges",
       .chapter = "08_fast_exact",
       .rule = CoverageRule::top_left,
       .summary = "fast_incremental testing the OR of the three edge values: one branch per pixel",
       .draw = draw_triangle_all_edges},
      {.name = "fast_spans",
       .chapter = "08_fast_exact",
       .rule = CoverageRule::top_left,
       .summary = "exact first and last covered pixel per row (division-free walker), spans filled",
       .draw = draw_triangle_spans},
      {.name = "fast_blocks_8x8",
       .chapter = "08_fast_exact",
       .rule = CoverageRule::top_left,
       .summary = "8x8 blocks: outside skipped, inside filled, partial ones tested per pixel",
       .draw = draw_triangle_blocks_8x8},
      {.name = "fast_simd",
       .chapter = "08_fast_exact",
       .rule = CoverageRule::top_left,
       .summary = "fast_blocks_8x8 testing eight pixels of a row at once in vectorizable lanes",
       .draw = draw_triangle_simd},
      {.name = "fast_hybrid",
       .chapter = "08_fast_exact",
       .rule = CoverageRule::top_left,
       .summary = "per triangle: fast_simd's eight-lane test within one 8x8 block, else fast_spans",
       .draw = draw_triangle_hybrid,
       .draw_batch = draw_batch_hybrid},
      {.name = "fast_threaded",
       .chapter = "08_fast_exact",
       .rule = CoverageRule::top_left,
       .summary = "fast_hybrid on bands of rows dealt to hardware_concurrency threads per batch",
       .draw = draw_triangle_hybrid,
       .threaded = true,
       .draw_batch = draw_batch_threaded},
  }};
  return algorithms;
}

}  // namespace tri::ch08
