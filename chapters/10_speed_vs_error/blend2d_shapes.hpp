/// @file
/// Blend2D's benchmark shapes in the report: bl_bench's FillTriangle test (three random points in
/// an N×N square placed anywhere on a 512×600 canvas, N = 8 to 256) drawn by the book's aliased
/// and anti-aliasing algorithms and by the peers, as render calls per millisecond (one triangle is
/// one call), written as a Markdown section, a CSV and a file in bl_bench's JSON layout so the
/// numbers can stand beside Blend2D's, Skia's and AGG's published charts.
#pragma once

#include <array>
#include <cstddef>
#include <ostream>
#include <span>
#include <string>
#include <vector>

#include "chapters/09_anti_aliasing/area_algorithms.hpp"
#include "chapters/10_speed_vs_error/suites.hpp"
#include "common/triangle_algorithm.hpp"
#include "measure/machine.hpp"
#include "measure/peers/peer.hpp"
#include "measure/timing.hpp"

namespace tri::ch10 {

inline constexpr const char* blend2d_shapes_csv_file_name = "10_blend2d_shapes.csv";
inline constexpr const char* blend2d_shapes_json_file_name = "10_blend2d_shapes.json";

/// bl_bench's shape sizes (its bench_shape_size_table) and default canvas.
inline constexpr std::array<int, 6> blend2d_box_sides{8, 16, 32, 64, 128, 256};
inline constexpr int blend2d_canvas_width = 512;
inline constexpr int blend2d_canvas_height = 600;

/// How much of the shapes a suite size draws.
struct Blend2dShapesSettings {
  int triangles = 0;  ///< triangles per size: one frame, every drawer draws all of them
  TimingPlan timing;
  /// The coverage peers measure their error with their time: on this many triangles only.
  std::size_t error_triangle_limit = 1;
};

/// tiny: 4 triangles per size, one run per sample; quick: 100 per size, samples of 5 ms; full:
/// 1000 per size, samples of 20 ms.
Blend2dShapesSettings blend2d_shapes_settings(SuiteSize size);

/// The scene of one size: `triangles` in_boxes triangles of side `box_side` on the 512×600
/// canvas, 1/256 grid, a seed of its own per size.
SuiteScene blend2d_shape_scene(int box_side, int triangles);

/// How a drawer writes a covered pixel.
enum class ShapeWrites {
  replace,  ///< the colour replaces the pixel (bl_bench's SrcCopy)
  add,      ///< coverage added to the pixel (bl_bench's Plus)
  over,     ///< coverage composited over the pixel as alpha (bl_bench's SrcOver)
  peer      ///< a peer's own writes, as its summary says (the report's first two parts)
};

/// "replace", "add", "over" or "peer".
std::string_view writes_name(ShapeWrites writes) noexcept;

/// One drawer at one size.
struct ShapeRate {
  std::string drawer;
  std::string chapter;  ///< the chapter folder, or "external" for a peer
  ShapeWrites writes = ShapeWrites::replace;
  int box_side = 0;
  std::size_t triangles = 0;
  Timing timing;  ///< seconds per frame (all the size's triangles)

  /// Triangles per millisecond of the median frame: bl_bench's render calls per millisecond.
  double calls_per_ms() const noexcept;
};

/// Every drawer at every size: the aliased algorithms timed against each other in interleaved
/// rounds, then the coverage algorithms the same way, then each peer on its own; one progress line
/// per drawer and size.
std::vector<ShapeRate> run_blend2d_shapes(std::span<const TriangleAlgorithm> algorithms,
                                          std::span<const ExternalPeer> peers,
                                          std::span<const ch09::AreaAlgorithm> area_algorithms,
                                          std::span<const CoveragePeer> coverage_peers,
                                          const Blend2dShapesSettings& settings,
                                          std::ostream& progress);

/// The vector copies this host runs ("AVX2", or "SSE2 (portable)"): what the numbers come from.
std::string host_instruction_set();

/// The header and one line per drawer and size.
std::string blend2d_shapes_csv(std::span<const ShapeRate> rows);

/// The Markdown section "Blend2D's benchmark shapes" (empty without rows): one table row per
/// drawer, a column per size, and which writes were not measured.
std::string blend2d_shapes_markdown(std::span<const ShapeRate> rows, const Machine& machine);

/// bl_bench's JSON layout: environment, cpu, screen, options (quantity, sizes, repeat), then one
/// run per drawer with one FillTriangle record whose "rcpms" holds a rate per size, formatted as
/// bl_bench formats them.
std::string bl_bench_json(std::span<const ShapeRate> rows, const Machine& machine);

}  // namespace tri::ch10
