/// @file
/// What an outside rasterizer measured beside the book's algorithms is, and what it gives back:
/// plain numbers, so they can come back from a child process. A peer is described by the same
/// Drawable as the book's algorithms (its name, its rule as a CoverageRule, what it writes,
/// whether it is threaded), in the chapter "external"; what it adds are the functions that
/// measure it, since it draws into its own buffer rather than a Canvas.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "measure/area_error.hpp"
#include "measure/drawable.hpp"
#include "measure/error_metrics.hpp"
#include "measure/prepared_scene.hpp"
#include "measure/timing.hpp"

namespace tri {

/// What an external rasterizer measured on one prepared scene.
struct PeerResult {
  Timing timing;                     ///< seconds per draw of the whole scene
  std::uint64_t written_pixels = 0;  ///< pixel writes of one draw of the scene
  ErrorReport error;                 ///< against the oracle, on the error scene
};

/// An external peer's result from its timing: the pixel writes of one draw of the scene by `draw`
/// and its error (measure_error with `draw`) on the error scene.
PeerResult peer_result(const Timing& timing, const CountingDraw& draw,
                       const PreparedScene& prepared);

/// The chapter the report files every peer under.
inline constexpr std::string_view external_chapter = "external";

/// A rasterizer that is not one of the book's (Mesa's llvmpipe, pixman, cairo), measured beside
/// them: its description (name, e.g. "mesa_llvmpipe_1_thread"; the rule it is shown to follow;
/// outputs {counts}) and how to measure it.
struct ExternalPeer : Drawable {
  std::string_view library;  ///< the library it comes from, as the report's status line names it
  /// Times it on the prepared scene (as measure does an algorithm) and measures its error.
  std::function<PeerResult(const PreparedScene&, const TimingPlan&)> measure;
  /// Times one draw of the prepared scene and nothing else (no counts, no error), in this
  /// process: the scaling sweeps call it in a child process of their own.
  std::function<Timing(const PreparedScene&, const TimingPlan&)> time;
  /// The write counts of triangles on a width x height canvas, in this process (llvmpipe starts
  /// Mesa here): what its adapter for the conformance suite (tools/peer_rasterizer) answers.
  CountingDraw write_counts;
};

/// The description of an aliased peer: chapter "external", outputs {counts}.
constexpr Drawable aliased_peer_description(std::string_view name, std::string_view summary,
                                            CoverageRule rule, bool threaded) noexcept {
  return {.name = name,
          .chapter = external_chapter,
          .summary = summary,
          .rule = rule,
          .outputs = {Output::counts},
          .threaded = threaded};
}

/// A peer measured in this process: `time` times one draw of the prepared scene, `draw` gives
/// the write counts its pixel writes and its error are taken from (peer_result).
ExternalPeer in_process_peer(const Drawable& description, std::string_view library,
                             std::function<Timing(const PreparedScene&, const TimingPlan&)> time,
                             CountingDraw draw);

/// The description of an anti-aliasing peer: chapter "external", rule area, outputs coverage16.
constexpr Drawable coverage_peer_description(std::string_view name,
                                             std::string_view summary) noexcept {
  return {.name = name,
          .chapter = external_chapter,
          .summary = summary,
          .rule = CoverageRule::area,
          .outputs = coverage_outputs};
}

/// What an anti-aliasing peer measured on one scene: plain numbers, as for the peers above.
struct CoveragePeerResult {
  Timing timing;                     ///< seconds per draw of the whole scene, one call per triangle
  std::uint64_t touched_pixels = 0;  ///< pixels with coverage above zero, each triangle on its own
  AreaErrorReport error;             ///< measure_area_error of its coverage against the truth
};

/// A rasterizer from outside the book that anti-aliases (AGG, cairo, pixman), measured beside
/// chapter 09's algorithms: its description (rule area, outputs coverage16; the summary says how
/// it computes the area, e.g. "area to 8 bits") and how to measure it.
struct CoveragePeer : Drawable {
  std::string_view library;  ///< the library it comes from, as the report's status line names it
  int samples = 0;           ///< samples per pixel when it samples; 0 when it computes the area
  /// Times it on the prepared scene (each triangle one call, as the book's algorithms are called)
  /// and measures its coverage against the truth of the error scene.
  std::function<CoveragePeerResult(const PreparedScene&, const AreaTruth& error_truth,
                                   const TimingPlan&)>
      measure;
};

}  // namespace tri
