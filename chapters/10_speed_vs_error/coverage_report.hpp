/// @file
/// The report's second part, on the coverage algorithms (rule `area`): one summary per algorithm,
/// 10_coverage.csv, the Markdown section and 10_coverage_speed_vs_error.svg.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "chapters/10_speed_vs_error/coverage_measure.hpp"
#include "chapters/10_speed_vs_error/measure.hpp"

namespace tri::ch10 {

/// A coverage algorithm or peer over a whole run.
struct CoverageSummary {
  std::string algorithm;
  std::string chapter;
  std::string rule;
  int samples = 0;
  int scenes = 0;
  double tris_per_s = 0;       ///< geometric mean over every scene: the plot's y
  double mean_error = 0;       ///< over every (triangle, pixel) pair of every scene: the plot's x
  double max_error = 0;        ///< the largest over every scene
  int max_units = 0;           ///< the largest 16-bit difference over every scene
  double seam_max = 0;         ///< composed error on the mesh scenes: the largest
  double cost_vs_fastest = 0;  ///< geometric mean over scenes of its time / chapter 08's fastest
};

/// The summaries in the order the algorithms first appear. `triangle_rows` are the first part's
/// rows: chapter 08's fastest single-thread time on each scene is the cost reference.
std::vector<CoverageSummary> summarize_coverage(std::span<const CoverageMeasurement> rows,
                                                std::span<const Measurement> triangle_rows);

/// The header and one line per measurement.
std::string coverage_csv(std::span<const CoverageMeasurement> rows);

/// The Markdown section "Coverage: rule area" (empty without rows). `peer_status` says which
/// anti-aliasing peers were measured.
std::string coverage_markdown(std::span<const CoverageSummary> summaries,
                              std::span<const CoverageMeasurement> rows,
                              const std::string& peer_status);

/// The plot: mean error across (log), triangles per second up (log), the sample counts joined into
/// curves, a dashed guide where error falls as 1/n.
std::string coverage_svg(std::span<const CoverageSummary> summaries, const std::string& subtitle);

}  // namespace tri::ch10
