/// @file
/// Measuring one algorithm on one scene (speed, pixels written, error against the oracle), and a
/// whole run: every algorithm on every scene of a suite.
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "chapters/10_speed_vs_error/suites.hpp"
#include "common/scene.hpp"
#include "common/triangle_algorithm.hpp"
#include "measure/error_metrics.hpp"
#include "measure/fill_ceiling.hpp"
#include "measure/machine.hpp"
#include "measure/peers/peer.hpp"
#include "measure/timing.hpp"

namespace tri::ch10 {

/// The write ceilings of one canvas size (measure/fill_ceiling.hpp), measured in the same run as
/// the algorithms: the faster of memset and vector stores, in one thread and in `threads`.
struct FillCeilings {
  FillCeiling one_thread;
  /// Filled by `threads` threads started for every fill, as a threaded algorithm starts them for
  /// every batch; on a small canvas starting them can cost more than the fill.
  FillCeiling all_threads;
  int threads = 1;

  double single_thread_mpix_per_s() const noexcept { return one_thread.mpix_per_s(); }
  /// The ceiling of a threaded algorithm: the faster of the two (it could use one thread).
  double threaded_mpix_per_s() const noexcept {
    return std::max(one_thread.mpix_per_s(), all_threads.mpix_per_s());
  }
};

/// Times the ceiling fills over a width x height canvas in one thread and in `threads` threads.
FillCeilings measure_fill_ceilings(int width, int height, int threads, const TimingPlan& plan);

/// The one-thread ceiling of a square canvas of another size than the suite's, for reference.
struct SizedCeiling {
  int side = 0;
  FillCeiling one_thread;
};

/// What names a row of either report part: who drew, and the scene drawn.
struct RowIdentity {
  std::string algorithm;
  std::string chapter;  ///< the chapter folder, or "external" for a peer
  std::string rule;
  std::string scene;
  std::string grid;
  bool mesh = false;
  int width = 0;
  int height = 0;
  std::size_t triangles = 0;
};

/// The identity of a row: the drawer's name, chapter and rule, and the prepared scene's.
RowIdentity row_identity(std::string_view name, std::string_view chapter, std::string_view rule,
                         const PreparedScene& prepared);

/// One algorithm on one scene: a row of the CSV.
struct Measurement : RowIdentity {
  bool threaded = false;
  std::string precision_family;  ///< the registry's precision family (empty for none)
  int precision_bits = 0;
  std::uint64_t written_pixels = 0;    ///< pixel writes of one draw of the scene (write counts)
  Timing timing;                       ///< seconds per draw of the whole scene
  double fill_ceiling_mpix_per_s = 0;  ///< the ceiling that applies: threaded or single thread
  std::size_t error_triangles = 0;     ///< triangles the error was measured on
  ErrorReport error;

  double triangles_per_second() const noexcept;
  /// Written pixels per second of the median draw, in millions.
  double mpix_per_second() const noexcept;
  /// mpix_per_second / fill_ceiling_mpix_per_s (0 without a ceiling).
  double ratio_to_ceiling() const noexcept;
};

/// Pixel writes of one draw of the triangles on a counting canvas of the scene's size.
std::uint64_t count_written_pixels(const TriangleAlgorithm& algorithm, const Scene& scene,
                                   std::span<const SceneTriangle> triangles);

/// Times every algorithm drawing the prepared scene's batch (checked once by prepare_scene), each
/// through one BatchDrawer kept for all its draws (a renderer's threads started once), against
/// each other in interleaved rounds (time_interleaved), on one canvas without write counts;
/// drawers and canvas are made before the clock starts. One Timing per algorithm, in order.
std::vector<Timing> time_algorithms(std::span<const TriangleAlgorithm> algorithms,
                                    const PreparedScene& prepared, const TimingPlan& plan);

/// The row of one algorithm on one prepared scene with its timing: pixels counted once in a
/// separate draw, and the error from measure_error on the error scene.
Measurement measure(const TriangleAlgorithm& algorithm, const PreparedScene& prepared,
                    const Timing& timing, const FillCeilings& ceilings);

/// Times one algorithm alone (time_algorithms of one) and measures it.
Measurement measure(const TriangleAlgorithm& algorithm, const PreparedScene& prepared,
                    const TimingPlan& plan, const FillCeilings& ceilings);

/// One external peer on one prepared scene, as a row like any algorithm's.
Measurement measure(const ExternalPeer& peer, const PreparedScene& prepared, const TimingPlan& plan,
                    const FillCeilings& ceilings);

/// Everything one run measured.
struct BenchReport {
  Machine machine;
  SuiteSize size = SuiteSize::quick;
  int width = 0;  ///< canvas of the suite (every scene of a suite has the same)
  int height = 0;
  std::size_t error_triangle_limit = 0;
  FillCeilings ceilings;  ///< medians over the scenes of the per-scene ceilings
  std::vector<SizedCeiling> reference_ceilings;  ///< settings.reference_canvas_sides, in order
  std::vector<Measurement> rows;                 ///< scene by scene, every algorithm on each
};

/// Runs every algorithm (timed in interleaved rounds), then every external peer, on every scene
/// of the settings, printing one progress line per (algorithm or peer, scene) to progress.
BenchReport run_benchmark(std::span<const TriangleAlgorithm> algorithms,
                          std::span<const ExternalPeer> peers, const BenchSettings& settings,
                          const Machine& machine, std::ostream& progress);

}  // namespace tri::ch10
