/// @file
/// One line per algorithm: its measurements over every scene of a run boiled down to a few
/// numbers (the Markdown table and the plot use these), and the precision families the plot
/// connects.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "chapters/10_speed_vs_error/measure.hpp"

namespace tri::ch10 {

/// An algorithm over a whole run. Speeds of one scene kind are the geometric mean of its
/// integer-grid and 1/256-grid runs; 0 when the run had no such scene.
struct AlgorithmSummary {
  std::string algorithm;
  std::string chapter;
  std::string rule;
  bool threaded = false;
  std::string precision_family;  ///< from the registry: algorithms differing only in precision
  int precision_bits = 0;
  int scenes = 0;               ///< measurements summarized
  double large_mpix_per_s = 0;  ///< written Mpixels/s on the "large" scenes
  double tiny_tris_per_s = 0;   ///< triangles/s on the "tiny" scenes
  double mesh_tris_per_s = 0;   ///< triangles/s on the "mesh" scenes
  double mpix_per_s = 0;        ///< geometric mean over every scene: the plot's y
  double ratio_to_ceiling = 0;  ///< geometric mean over every scene of Mpix/s / ceiling
  std::uint64_t covered = 0;    ///< oracle pixels over every scene's error measurement
  std::uint64_t missed = 0;
  std::uint64_t extra = 0;
  std::uint64_t gaps = 0;      ///< on mesh scenes only
  std::uint64_t overdraw = 0;  ///< on mesh scenes only
  std::uint64_t order_dependent = 0;
  std::uint64_t outside_writes = 0;

  /// (missed + extra) per covered pixel over every scene: the plot's x.
  double error_rate() const noexcept;
};

/// Summaries of the algorithms in the order they first appear in rows.
std::vector<AlgorithmSummary> summarize(std::span<const Measurement> rows);

/// The precision families (the registry's precision_family) with at least two members among the
/// summaries: each a list of indices into summaries, from the fewest bits to the most. Members
/// must share the chapter too.
std::vector<std::vector<std::size_t>> precision_families(
    std::span<const AlgorithmSummary> summaries);

}  // namespace tri::ch10
