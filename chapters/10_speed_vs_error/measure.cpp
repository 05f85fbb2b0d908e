#include "chapters/10_speed_vs_error/measure.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <numeric>
#include <stdexcept>

#include "measure/render_scene.hpp"

namespace tri::ch10 {

FillCeilings measure_fill_ceilings(int width, int height, int threads, const TimingPlan& plan) {
  Canvas canvas(width, height);
  FillCeilings ceilings;
  ceilings.threads = std::max(1, threads);
  ceilings.one_thread = measure_fill_ceiling(canvas, 1, plan);
  ceilings.all_threads = ceilings.threads == 1
                             ? ceilings.one_thread
                             : measure_fill_ceiling(canvas, ceilings.threads, plan);
  return ceilings;
}

RowIdentity row_identity(std::string_view name, std::string_view chapter, std::string_view rule,
                         const PreparedScene& prepared) {
  return {.algorithm = std::string(name),
          .chapter = std::string(chapter),
          .rule = std::string(rule),
          .scene = prepared.suite.name,
          .grid = prepared.suite.grid,
          .mesh = prepared.suite.mesh,
          .width = prepared.scene.width,
          .height = prepared.scene.height,
          .triangles = prepared.triangles.size()};
}

double Measurement::triangles_per_second() const noexcept {
  const double seconds = timing.seconds.median;
  return seconds > 0 ? static_cast<double>(triangles) / seconds : 0.0;
}

double Measurement::mpix_per_second() const noexcept {
  return tri::mpix_per_second(static_cast<double>(written_pixels), timing.seconds.median);
}

double Measurement::ratio_to_ceiling() const noexcept {
  return fill_ceiling_mpix_per_s > 0 ? mpix_per_second() / fill_ceiling_mpix_per_s : 0.0;
}

std::uint64_t count_written_pixels(const TriangleAlgorithm& algorithm, const Scene& scene,
                                   std::span<const SceneTriangle> triangles) {
  const WriteCounts drawn = draw_write_counts(algorithm, scene.width, scene.height, triangles);
  return std::accumulate(drawn.counts.begin(), drawn.counts.end(), std::uint64_t{0});
}

namespace {

// A row with what the scene and the drawer say about themselves, before anything is measured.
Measurement row_for(std::string_view name, std::string_view chapter, std::string_view rule,
                    bool threaded, const PreparedScene& prepared, const FillCeilings& ceilings) {
  Measurement m;
  static_cast<RowIdentity&>(m) = row_identity(name, chapter, rule, prepared);
  m.threaded = threaded;
  m.fill_ceiling_mpix_per_s =
      threaded ? ceilings.threaded_mpix_per_s() : ceilings.single_thread_mpix_per_s();
  m.error_triangles = count_triangles(prepared.error_scene);
  return m;
}

}  // namespace

std::vector<Timing> time_algorithms(std::span<const TriangleAlgorithm> algorithms,
                                    const PreparedScene& prepared, const TimingPlan& plan) {
  Canvas canvas = make_canvas(prepared.scene);  // no write counts: they would be timed too
  const PreparedBatch& batch = prepared.batch;  // checked once, by prepare_scene
  if (batch.triangles().size() + batch.refused() != prepared.triangles.size())
    throw std::logic_error("time_algorithms needs a scene made by prepare_scene");
  // Each algorithm's drawer is made before the clock runs and kept for all its draws: a
  // renderer's threads are started once, as a real renderer's are.
  std::vector<BatchDrawer> drawers(algorithms.begin(), algorithms.end());
  std::vector<std::function<void()>> draws;
  for (BatchDrawer& drawer : drawers)
    draws.emplace_back([&canvas, &drawer, &batch] { drawer.draw(canvas, batch); });
  return time_interleaved(draws, plan);
}

// [listing measure]
Measurement measure(const TriangleAlgorithm& algorithm, const PreparedScene& prepared,
                    const Timing& timing, const FillCeilings& ceilings) {
  Measurement m = row_for(algorithm.name, algorithm.chapter, rule_name(algorithm.rule),
                          algorithm.threaded, prepared, ceilings);
  m.precision_family = algorithm.precision_family;
  m.precision_bits = algorithm.precision_bits;
  m.written_pixels = count_written_pixels(algorithm, prepared.scene, prepared.triangles);
  m.timing = timing;
  m.error = measure_error(algorithm, prepared.error_scene);
  return m;
}
// [/listing]

Measurement measure(const TriangleAlgorithm& algorithm, const PreparedScene& prepared,
                    const TimingPlan& plan, const FillCeilings& ceilings) {
  const Timing timing = time_algorithms(std::span(&algorithm, 1), prepared, plan).front();
  return measure(algorithm, prepared, timing, ceilings);
}

Measurement measure(const ExternalPeer& peer, const PreparedScene& prepared, const TimingPlan& plan,
                    const FillCeilings& ceilings) {
  Measurement m =
      row_for(peer.name, peer.chapter, rule_name(peer.rule), peer.threaded, prepared, ceilings);
  const PeerResult result = peer.measure(prepared, plan);
  m.timing = result.timing;
  m.written_pixels = result.written_pixels;
  m.error = result.error;
  return m;
}

namespace {

double median_of(std::vector<double> values) {
  return values.empty() ? 0.0 : spread_of(std::move(values)).median;
}

// The median of each fill's rate over the scenes' ceilings.
FillCeiling median_ceiling(const std::vector<FillCeiling>& ceilings) {
  std::vector<double> memset, stores;
  for (const FillCeiling& c : ceilings) {
    memset.push_back(c.memset_mpix_per_s);
    stores.push_back(c.vector_stores_mpix_per_s);
  }
  return {median_of(std::move(memset)), median_of(std::move(stores))};
}

std::string progress_line(std::size_t done, std::size_t total, const Measurement& m,
                          double elapsed_seconds) {
  char line[256];
  std::snprintf(line, sizeof line, "[%3zu/%zu] %-8s %-7s %-28s %9.2f Mpix/s  error %.3g  (%.1f s)",
                done, total, m.scene.c_str(), m.grid.c_str(), m.algorithm.c_str(),
                m.mpix_per_second(), m.error.error_rate(), elapsed_seconds);
  return line;
}

}  // namespace

BenchReport run_benchmark(std::span<const TriangleAlgorithm> algorithms,
                          std::span<const ExternalPeer> peers, const BenchSettings& settings,
                          const Machine& machine, std::ostream& progress) {
  BenchReport report;
  report.machine = machine;
  report.size = settings.size;
  report.error_triangle_limit = settings.error_triangle_limit;
  const auto start = std::chrono::steady_clock::now();
  const std::size_t total = settings.scenes.size() * (algorithms.size() + peers.size());
  for (const int side : settings.reference_canvas_sides) {
    Canvas canvas(side, side);
    report.reference_ceilings.push_back({side, measure_fill_ceiling(canvas, 1, settings.timing)});
  }
  std::vector<FillCeiling> single_ceilings, threaded_ceilings;
  for (const SuiteScene& suite : settings.scenes) {
    const PreparedScene prepared = prepare_scene(suite, settings.error_triangle_limit);
    report.width = prepared.scene.width;
    report.height = prepared.scene.height;
    const FillCeilings ceilings =
        measure_fill_ceilings(prepared.scene.width, prepared.scene.height,
                              static_cast<int>(std::max(1u, machine.threads)), settings.timing);
    single_ceilings.push_back(ceilings.one_thread);
    threaded_ceilings.push_back(ceilings.all_threads);
    report.ceilings.threads = ceilings.threads;
    const auto record = [&](Measurement row) {
      report.rows.push_back(std::move(row));
      const double elapsed =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      progress << progress_line(report.rows.size(), total, report.rows.back(), elapsed)
               << std::endl;  // flushed: the line is the progress
    };
    // The algorithms are timed against each other in interleaved rounds, then measured one by one.
    const std::vector<Timing> timings = time_algorithms(algorithms, prepared, settings.timing);
    for (std::size_t i = 0; i < algorithms.size(); ++i) {
      record(measure(algorithms[i], prepared, timings[i], ceilings));
    }
    for (const ExternalPeer& peer : peers)
      record(measure(peer, prepared, settings.timing, ceilings));
  }
  report.ceilings.one_thread = median_ceiling(single_ceilings);
  report.ceilings.all_threads = median_ceiling(threaded_ceilings);
  return report;
}

}  // namespace tri::ch10
