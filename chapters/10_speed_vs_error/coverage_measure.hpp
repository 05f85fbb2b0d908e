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

#include "chapters/09_anti_aliasing/area_algorithms.hpp"
#include "chapters/10_speed_vs_error/measure.hpp"
#include "measure/area_error.hpp"
#include "measure/peers/peer.hpp"
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

/// Times every coverage algorithm drawing the prepared scene, against each other in interleaved
/// rounds (time_interleaved), each on a canvas of its own made before the clock and not cleared
/// between runs. One Timing per algorithm, in order.
std::vector<Timing> time_area_algorithms(std::span<const ch09::AreaAlgorithm> algorithms,
                                         const PreparedScene& prepared, const TimingPlan& plan);

/// Times every coverage algorithm on every scene of the settings (interleaved rounds, one canvas
/// per algorithm, not cleared between runs), measures its error against the exact area of the
/// error scene (computed once per scene), then every peer; one progress line per row.
std::vector<CoverageMeasurement> run_coverage_benchmark(
    std::span<const ch09::AreaAlgorithm> algorithms, std::span<const CoveragePeer> peers,
    const BenchSettings& settings, std::ostream& progress);

}  // namespace tri::ch10
