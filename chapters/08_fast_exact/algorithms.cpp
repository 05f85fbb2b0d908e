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
      {"fast_incremental", "08_fast_exact", CoverageRule::top_left,
       "fixed_point_8 with edge values updated by one addition per pixel and edge",
       draw_triangle_incremental},
      {"fast_all_edges", "08_fast_exact", CoverageRule::top_left,
       "fast_incremental testing the OR of the three edge values: one branch per pixel",
       draw_triangle_all_edges},
      {"fast_spans", "08_fast_exact", CoverageRule::top_left,
       "exact first and last covered pixel per row (division-free walker), spans filled",
       draw_triangle_spans},
      {"fast_blocks_8x8", "08_fast_exact", CoverageRule::top_left,
       "8x8 blocks: outside skipped, inside filled, partial ones tested per pixel",
       draw_triangle_blocks_8x8},
      {"fast_simd", "08_fast_exact", CoverageRule::top_left,
       "fast_blocks_8x8 testing eight pixels of a row at once in vectorizable lanes",
       draw_triangle_simd},
      {"fast_hybrid", "08_fast_exact", CoverageRule::top_left,
       "per triangle: fast_simd's eight-lane test within one 8x8 block, else fast_spans",
       draw_triangle_hybrid, false, draw_batch_hybrid},
      {"fast_threaded", "08_fast_exact", CoverageRule::top_left,
       "fast_hybrid on bands of rows dealt to hardware_concurrency threads per batch",
       draw_triangle_hybrid, true, draw_batch_threaded},
  }};
  return algorithms;
}

}  // namespace tri::ch08
