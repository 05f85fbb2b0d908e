#include "chapters/10_speed_vs_error/coverage_measure.hpp"

#include <chrono>
#include <cstdio>

namespace tri::ch10 {

double CoverageMeasurement::triangles_per_second() const noexcept {
  const double seconds = timing.seconds.median;
  return seconds > 0 ? static_cast<double>(triangles) / seconds : 0.0;
}

namespace {

CoverageMeasurement row_for(std::string_view name, std::string_view chapter, std::string_view rule,
                            int samples, const PreparedScene& prepared) {
  CoverageMeasurement m;
  static_cast<RowIdentity&>(m) = row_identity(name, chapter, rule, prepared);
  m.samples = samples;
  return m;
}

std::string progress_line(std::size_t done, std::size_t total, const CoverageMeasurement& m,
                          double elapsed_seconds) {
  char line[256];
  std::snprintf(line, sizeof line,
                "[%3zu/%zu] %-8s %-7s %-28s %9.3g tris/s  mean error %.3g  (%.1f s)", done, total,
                m.scene.c_str(), m.grid.c_str(), m.algorithm.c_str(), m.triangles_per_second(),
                m.error.mean, elapsed_seconds);
  return line;
}

}  // namespace

std::vector<Timing> time_area_algorithms(std::span<const ch09::AreaAlgorithm> algorithms,
                                         const PreparedScene& prepared, const TimingPlan& plan) {
  // One canvas each, allocated before the clock starts; timed against each other.
  std::vector<ch09::CoverageCanvas> canvases(
      algorithms.size(), ch09::CoverageCanvas(prepared.scene.width, prepared.scene.height));
  std::vector<std::function<void()>> runs;
  for (std::size_t i = 0; i < algorithms.size(); ++i) {
    runs.emplace_back([&, i] { algorithms[i].draw(canvases[i], prepared.triangles); });
  }
  return time_interleaved(runs, plan);
}

std::vector<CoverageMeasurement> run_coverage_benchmark(
    std::span<const ch09::AreaAlgorithm> algorithms, std::span<const CoveragePeer> peers,
    const BenchSettings& settings, std::ostream& progress) {
  std::vector<CoverageMeasurement> rows;
  const auto start = std::chrono::steady_clock::now();
  const std::size_t total = settings.scenes.size() * (algorithms.size() + peers.size());
  const auto record = [&](CoverageMeasurement row) {
    rows.push_back(std::move(row));
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    progress << progress_line(rows.size(), total, rows.back(), elapsed) << std::endl;
  };
  for (const SuiteScene& suite : settings.scenes) {
    const PreparedScene prepared = prepare_scene(suite, settings.error_triangle_limit);
    const AreaTruth truth(prepared.error_scene);  // the oracle once, for every algorithm
    const std::vector<Timing> timings = time_area_algorithms(algorithms, prepared, settings.timing);
    for (std::size_t i = 0; i < algorithms.size(); ++i) {
      const ch09::AreaAlgorithm& a = algorithms[i];
      CoverageMeasurement m = row_for(a.name, a.chapter, rule_name(a.rule), a.samples, prepared);
      m.timing = timings[i];
      m.touched_pixels =
          touched_pixels(a, prepared.scene.width, prepared.scene.height, prepared.triangles);
      m.error = measure_area_error(
          [&](ch09::CoverageCanvas& canvas, std::span<const SceneTriangle> triangles) {
            ch09::draw_coverage(a, canvas, triangles);
          },
          truth);
      record(std::move(m));
    }
    for (const CoveragePeer& peer : peers) {
      CoverageMeasurement m =
          row_for(peer.name, peer.chapter, rule_name(peer.rule), peer.samples, prepared);
      const CoveragePeerResult result = peer.measure(prepared, truth, settings.timing);
      m.timing = result.timing;
      m.touched_pixels = result.touched_pixels;
      m.error = result.error;
      record(std::move(m));
    }
  }
  return rows;
}

}  // namespace tri::ch10
