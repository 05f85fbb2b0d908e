/// @file
/// What an outside rasterizer measured beside the book's algorithms is, and what it gives back:
/// plain numbers, so they can come back from a child process.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "measure/area_error.hpp"
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

/// A rasterizer that is not one of the book's (Mesa's llvmpipe), measured beside them.
struct ExternalPeer {
  std::string name;     ///< its row in the report, e.g. "mesa_llvmpipe_1_thread"
  std::string chapter;  ///< where the report files it: "external"
  std::string rule;     ///< what it is expected to follow
  bool threaded = false;
  /// Times it on the prepared scene (as measure does an algorithm) and measures its error.
  std::function<PeerResult(const PreparedScene&, const TimingPlan&)> measure;
  /// Times one draw of the prepared scene and nothing else (no counts, no error), in this
  /// process: the scaling sweeps call it in a child process of their own.
  std::function<Timing(const PreparedScene&, const TimingPlan&)> time;
};

/// What an anti-aliasing peer measured on one scene: plain numbers, as for the peers above.
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

}  // namespace tri
