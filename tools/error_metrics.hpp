/// @file
/// How wrong an algorithm is on a scene, measured against the exact oracle (DESIGN section 6).
#pragma once

#include <cstdint>

#include "scene.hpp"
#include "triangle_algorithm.hpp"

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

/// Draws the scene's triangles with the algorithm and with the oracle (chapter 07) and compares
/// the write counts; then draws it in the five other vertex orders to find order dependence.
/// Lines are ignored.
ErrorReport measure_error(const TriangleAlgorithm& algorithm, const Scene& scene);

}  // namespace tri
