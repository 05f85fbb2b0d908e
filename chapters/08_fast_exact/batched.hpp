/// @file
/// Step 10 · set up several triangles at once: the per-triangle setup of triangle_setup.cpp
/// computed for setup_lanes triangles side by side in vector lanes (a structure of arrays), then
/// each triangle filled in submission order by step 6's fill_hybrid.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "chapters/08_fast_exact/instruction_sets.hpp"
#include "chapters/08_fast_exact/pixel_writers.hpp"
#include "chapters/08_fast_exact/triangle_setup.hpp"
#include "common/canvas.hpp"
#include "common/color.hpp"
#include "common/scene.hpp"
#include "common/triangle_algorithm.hpp"

namespace tri::ch08 {

/// How many triangles one pass of set_up_lanes sets up side by side.
inline constexpr int setup_lanes = 8;

/// The largest |coordinate| in pixels that the lanes set up: 2^16. Snapped, that is at most 2^24
/// sub-pixel units, so every number the lanes form (vertex differences below 2^25, products
/// below 2^50, twice the area below 2^51) is an integer that a double holds exactly. A triangle
/// with a vertex farther out is set up by setup_triangle instead (LaneResult::scalar).
inline constexpr double max_lane_coordinate = 65536.0;

/// What set_up_lanes did with one lane's triangle.
enum class LaneResult : std::uint8_t {
  nothing = 0,  ///< set up in lanes: zero area or no candidate pixel, nothing to draw
  set_up = 1,   ///< set up in lanes: SetupLanes::setup gives it
  scalar = 2    ///< a vertex beyond max_lane_coordinate: call setup_triangle for it
};

/// Up to setup_lanes triangles set up at once, each field one array over the lanes (structure
/// of arrays). Fields of lanes whose result is not `set_up` hold no meaning.
struct SetupLanes {
  std::array<LaneResult, setup_lanes> result;
  /// Edge e of lane i is {value[e][i], step_x[e][i], step_y[e][i]}, as in TriangleSetup.
  std::array<std::array<std::int64_t, setup_lanes>, 3> value, step_x, step_y;
  /// The candidate pixels, as whole numbers of the lanes' width.
  std::array<std::int64_t, setup_lanes> min_x, min_y, max_x, max_y;
  std::array<std::int64_t, setup_lanes> vertex_extent, middle_y;

  /// Lane i's fields gathered into the TriangleSetup that setup_triangle gives for the same
  /// triangle (result[i] must be `set_up`).
  TriangleSetup setup(int lane) const noexcept {
    const auto i = static_cast<std::size_t>(lane);
    return {{EdgeFunction{value[0][i], step_x[0][i], step_y[0][i]},
             EdgeFunction{value[1][i], step_x[1][i], step_y[1][i]},
             EdgeFunction{value[2][i], step_x[2][i], step_y[2][i]}},
            {{static_cast<int>(min_x[i]), static_cast<int>(min_y[i])},
             {static_cast<int>(max_x[i]), static_cast<int>(max_y[i])}},
            vertex_extent[i],
            middle_y[i]};
  }
};

/// Sets up the first min(setup_lanes, size) triangles of `triangles` for a width x height canvas
/// (at most 16384 a side) in lanes: the same snapping, zero-area cull, counter-clockwise order,
/// candidate pixels, edges with the top-left bias and extent as setup_triangle. Vertices must be
/// finite (draw_triangles checks them); lanes beyond the triangles given are `nothing`. In the
/// copy for `set` (by default the widest the host runs): SSE2's two lanes per instruction (as
/// generic vectors, any target's), or AVX2's four. Every copy gives the same numbers.
void set_up_lanes(std::span<const SceneTriangle> triangles, int width, int height,
                  SetupLanes& lanes, InstructionSet set = widest_instruction_set()) noexcept;

/// set_up_lanes for the first min(setup_lanes, size) triangles of `group`, then visit(i, setup)
/// for each triangle i that covers a pixel, in order (a lane's setup, or setup_triangle's for a
/// vertex beyond max_lane_coordinate); `lanes` is the caller's scratch.
template <class Visit>
void for_each_group_setup(std::span<const SceneTriangle> group, int width, int height,
                          SetupLanes& lanes, InstructionSet set, Visit&& visit) {
  set_up_lanes(group, width, height, lanes, set);
  for (std::size_t i = 0; i < std::min<std::size_t>(group.size(), setup_lanes); ++i) {
    if (lanes.result[i] == LaneResult::set_up) {
      visit(i, lanes.setup(static_cast<int>(i)));
    } else if (lanes.result[i] == LaneResult::scalar) {
      if (const auto setup = setup_triangle(group[i].vertices, width, height)) visit(i, *setup);
    }
  }
}

/// Step 10 · one group: set_up_lanes for the first min(setup_lanes, size) triangles of `group`,
/// then fill_hybrid for each in order with a Writer whose rows end at `row_end` (the canvas
/// width, or a tile's right border); `lanes` is the caller's scratch.
template <PixelWriter Writer>
void draw_group(Canvas& canvas, std::span<const SceneTriangle> group, int row_end,
                SetupLanes& lanes, InstructionSet set = widest_instruction_set());
extern template void draw_group<RowWriter>(Canvas&, std::span<const SceneTriangle>, int,
                                           SetupLanes&, InstructionSet);
extern template void draw_group<CountingWriter>(Canvas&, std::span<const SceneTriangle>, int,
                                                SetupLanes&, InstructionSet);

/// Step 10 · one triangle: set_up_lanes with one lane used, then fill_hybrid.
void draw_triangle_batched(Canvas& canvas, const Triangle& triangle, Color color);

/// Above these, draw_batch_batched draws through step 9's tiles on the calling thread: a canvas
/// of more than 1024 x 1024 pixels (4 MiB of RGBA8, four times this machine's level-2 caches
/// together) and a batch of at least 64 triangles.
inline constexpr std::int64_t tiled_canvas_pixels = 1024 * 1024;
inline constexpr std::size_t tiled_batch_triangles = 64;

/// Step 10 · a batch: set_up_lanes for each group of setup_lanes triangles, then fill_hybrid
/// for each of them in submission order, so the pixels are draw_batch_hybrid's; on a large
/// canvas (tiled_canvas_pixels, tiled_batch_triangles), the same through step 9's tiles.
void draw_batch_batched(Canvas& canvas, std::span<const SceneTriangle> triangles);
/// Step 10 · a batch into one of step 8's narrow canvases: set_up_lanes for each group of
/// setup_lanes triangles, then each in order through fill_spans and the narrow writer, or, on the
/// mask, fill_mask_lanes for a triangle it fits (fits_mask_lanes) (the registry's draw_narrow
/// entry of fast_batched): the pixels of draw_narrow_spans.
void draw_narrow_batched(NarrowTarget& target, std::span<const SceneTriangle> triangles);
/// The same with the lanes' copy for `set`.
void draw_narrow_batched_with(NarrowTarget& target, std::span<const SceneTriangle> triangles,
                              InstructionSet set);

/// The groups alone, with the lanes' copy for `set` (the tests force each the host runs).
void draw_batch_batched_with(Canvas& canvas, std::span<const SceneTriangle> triangles,
                             InstructionSet set);

}  // namespace tri::ch08
