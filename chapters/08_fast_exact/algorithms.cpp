#include "chapters/08_fast_exact/algorithms.hpp"

#include <array>
#include <string_view>

#include "chapters/08_fast_exact/batched.hpp"
#include "chapters/08_fast_exact/blocks.hpp"
#include "chapters/08_fast_exact/hybrid.hpp"
#include "chapters/08_fast_exact/incremental.hpp"
#include "chapters/08_fast_exact/narrow_canvases.hpp"
#include "chapters/08_fast_exact/simd.hpp"
#include "chapters/08_fast_exact/spans.hpp"
#include "chapters/08_fast_exact/threaded.hpp"
#include "chapters/08_fast_exact/tiled.hpp"

namespace tri::ch08 {
namespace {

// Every variant of the chapter keeps the top-left rule exactly; only its name, its summary and
// its entry points differ.
constexpr TriangleAlgorithm variant(std::string_view name, std::string_view summary,
                                    DrawTriangleFunction draw,
                                    DrawBatchFunction draw_batch = nullptr, bool threaded = false,
                                    MakeRendererFunction make_renderer = nullptr) {
  return {.name = name,
          .chapter = "08_fast_exact",
          .rule = CoverageRule::top_left,
          .summary = summary,
          .draw = draw,
          .threaded = threaded,
          .draw_batch = draw_batch,
          .make_renderer = make_renderer};
}

// The variant that also draws step 8's narrow canvases (index8, mask1).
constexpr TriangleAlgorithm with_narrow_formats(TriangleAlgorithm algorithm,
                                                DrawNarrowFunction draw_narrow) {
  algorithm.outputs = narrow_outputs;
  algorithm.draw_narrow = draw_narrow;
  return algorithm;
}

// The variant the report's cost sweeps follow.
constexpr TriangleAlgorithm followed_by_cost_sweeps(TriangleAlgorithm algorithm) {
  algorithm.role = Role::cost_sweeps;
  return algorithm;
}

// A variant with a band-limited entry, so a huge triangle's work can be split into bands of rows.
constexpr TriangleAlgorithm with_rows(TriangleAlgorithm algorithm, DrawTriangleRowsFunction rows) {
  algorithm.draw_rows = rows;
  return algorithm;
}

// A variant that is a step's fill on the canvas (OnCanvas): its draw, and its draw_rows.
template <CanvasFill fill>
constexpr TriangleAlgorithm filled_by(std::string_view name, std::string_view summary,
                                      DrawBatchFunction draw_batch = nullptr) {
  return with_rows(variant(name, summary, OnCanvas<fill>::draw, draw_batch),
                   OnCanvas<fill>::draw_rows);
}

}  // namespace

std::span<const TriangleAlgorithm> triangle_algorithms() {
  static constexpr auto algorithms = std::to_array<TriangleAlgorithm>({
      with_rows(variant("fast_incremental",
                        "fixed_point_8 with edge values updated by one addition per pixel and edge",
                        draw_triangle_incremental),
                draw_triangle_incremental_rows),
      with_rows(
          variant("fast_all_edges",
                  "fast_incremental testing the OR of the three edge values: one branch per pixel",
                  draw_triangle_all_edges),
          draw_triangle_all_edges_rows),
      with_narrow_formats(
          filled_by<fill_spans>(
              "fast_spans",
              "exact first and last covered pixel per row (division-free walker), spans filled"),
          draw_narrow_spans),
      filled_by<fill_blocks_8x8>(
          "fast_blocks_8x8",
          "8x8 blocks: outside skipped, inside filled, partial ones tested per pixel"),
      filled_by<fill_simd>(
          "fast_simd",
          "fast_blocks_8x8 testing eight pixels of a row at once in vectorizable lanes"),
      followed_by_cost_sweeps(filled_by<fill_hybrid>(
          "fast_hybrid",
          "per triangle: fast_simd's eight-lane test within one 8x8 block, else fast_spans",
          draw_batch_hybrid)),
      variant("fast_threaded",
              "fast_hybrid on bands of rows dealt to hardware_concurrency threads per batch",
              draw_triangle_hybrid, draw_batch_threaded, true),
      variant("fast_tiled_threaded",
              "fast_hybrid per tile: the batch binned into tiles, which hardware_concurrency "
              "threads (started once, kept between batches) take one at a time",
              draw_triangle_hybrid, nullptr, true, make_tiled_renderer),
      with_narrow_formats(
          with_rows(
              variant("fast_batched",
                      "fast_hybrid with the setup of eight triangles at once in vector lanes, then "
                      "each filled in order",
                      draw_triangle_batched, draw_batch_batched),
              OnCanvas<fill_hybrid>::draw_rows),
          draw_narrow_batched),
  });
  return algorithms;
}

}  // namespace tri::ch08
