/// @file
/// The report's second part: the coverage algorithms (rule `area`, chapter 09) and the peers that
/// anti-alias, timed on the same scenes and compared with the exact area.
#pragma once

#include <cstdint>
#include <functional>
#include <ostream>
#include <span>
#include <string>
#include <vector>

#include "chapters/10_speed_vs_error/measure.hpp"
#include "chapters/09_anti_aliasing/area_algorithms.hpp"
#include "measure/area_error.hpp"
#include "measure/timing.hpp"

namespace tri::ch10 {

/// One coverage algorithm or peer on one scene: a row of 10_coverage.csv.
/// chapter is "09_anti_aliasing" or "external"; rule is "area", or what a peer computes.
struct CoverageMeasurement : RowIdentity {
  int samples = 0;                   ///< samples per pixel; 0 for an exact-area method
  std::uint64_t touched_pixels = 0;  ///< pixels each triangle touches, each triangle on its own
  Timing timing;                     ///< seconds per draw of the whole scene
  AreaErrorReport error;             ///< against the exact area, on the error scene

  double triangles_per_second() const noexcept;
};

/// What a peer measured on one scene: plain numbers, as for the inside-or-outside peers.
struct CoveragePeerResult {
  Timing timing;                     ///< seconds per draw of the whole scene, one call per triangle
  std::uint64_t touched_pixels = 0;  ///< pixels with coverage above zero, each triangle on its own
  AreaErrorReport error;             ///< measure_area_error of its coverage against the truth
};

/// A rasterizer from outside the book that anti-aliases (AGG, cairo, pixman), measured beside
/// chapter 09's algorithms.
struct CoveragePeer {
  std::string name;  ///< its row, e.g. "agg_scanline_aa"
  std::string rule;  ///< what it computes, e.g. "area to 8 bits" (no commas: a CSV field)
  int samples = 0;   ///< samples per pixel when it samples; 0 when it computes the area
  /// Times it on the prepared scene (each triangle one call, as the book's algorithms are called)
  /// and measures its coverage against the truth of the error scene.
  std::function<CoveragePeerResult(const PreparedScene&, const AreaTruth& error_truth,
                                   const TimingPlan&)>
      measure;
};

/// Times every coverage algorithm on every scene of the settings (interleaved rounds, one canvas
/// per algorithm, not cleared between runs), measures its error against the exact area of the
/// error scene (computed once per scene), then every peer; one progress line per row.
std::vector<CoverageMeasurement> run_coverage_benchmark(
    std::span<const ch09::AreaAlgorithm> algorithms, std::span<const CoveragePeer> peers,
    const BenchSettings& settings, std::ostream& progress);

}  // namespace tri::ch10
