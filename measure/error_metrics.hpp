/// @file
/// How wrong an algorithm is on a scene, measured against the exact oracle
/// (@ref design_error "docs/DESIGN.md section 6").
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "common/scene.hpp"
#include "common/triangle_algorithm.hpp"

namespace tri {

/// Error counts of one algorithm on one scene. Counts compare per-pixel write counts, so a pixel
/// drawn twice where the truth draws it once is one extra.
struct ErrorReport {
  std::uint64_t covered = 0;   ///< sum of the oracle's counts: the pixels that should be drawn
  std::uint64_t missed = 0;    ///< sum over pixels of max(0, oracle - algorithm)
  std::uint64_t extra = 0;     ///< sum over pixels of max(0, algorithm - oracle)
  std::uint64_t gaps = 0;      ///< pixels the oracle covers that the algorithm never drew
  std::uint64_t overdraw = 0;  ///< pixels drawn more than once and more often than the oracle
  std::uint64_t order_dependent = 0;  ///< pixels whose count changes with the vertex order
  std::uint64_t outside_writes = 0;   ///< writes the algorithm attempted outside the canvas
  std::uint64_t rejected = 0;         ///< triangles refused (non-finite or out-of-range input)

  /// (missed + extra) per covered pixel (0 when nothing is covered and nothing was drawn).
  double error_rate() const noexcept;
  /// No deviation from the oracle of any kind.
  bool exact() const noexcept {
    return missed == 0 && extra == 0 && gaps == 0 && overdraw == 0 && order_dependent == 0 &&
           outside_writes == 0 && rejected == 0;
  }
};

/// What one drawing of a scene's triangles left behind: how often each pixel was written (row by
/// row from the bottom, as Canvas::write_counts) and what could not be drawn.
struct WriteCounts {
  std::vector<std::uint32_t> counts;
  std::uint64_t outside_writes = 0;  ///< writes attempted outside the canvas
  std::uint64_t rejected = 0;        ///< triangles refused
};

/// Draws triangles on a fresh width x height canvas and returns its write counts: the one thing
/// measure_error needs from a rasterizer, so one outside the registry (e.g. Mesa's) can be
/// measured.
using CountingDraw =
    std::function<WriteCounts(int width, int height, std::span<const SceneTriangle> triangles)>;

/// Draws the scene's triangles with the algorithm and with the oracle (chapter 07) and compares
/// the write counts; then draws it in the five other vertex orders to find order dependence.
/// Lines are ignored.
ErrorReport measure_error(const TriangleAlgorithm& algorithm, const Scene& scene);

/// The same measurement for any rasterizer that can report write counts.
ErrorReport measure_error(const CountingDraw& draw, const Scene& scene);

/// The write counts of the algorithm drawing the triangles (draw_triangles on a counting canvas).
WriteCounts draw_write_counts(const TriangleAlgorithm& algorithm, int width, int height,
                              std::span<const SceneTriangle> triangles);

}  // namespace tri
