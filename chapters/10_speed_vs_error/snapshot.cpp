#include "chapters/10_speed_vs_error/snapshot.hpp"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <sstream>

#include "chapters/10_speed_vs_error/coverage_report.hpp"
#include "chapters/10_speed_vs_error/summary.hpp"
#include "measure/number_format.hpp"

namespace tri::ch10 {
namespace {

// Six significant digits: the Markdown rounds further, ratios of two keys stay accurate.
constexpr int kDigits = 6;

class KeyValues {
 public:
  void add(const std::string& key, double value) {
    text_ << key << ',' << format_number(value, kDigits) << '\n';
  }
  void add(const std::string& key, const std::string& text) { text_ << key << ',' << text << '\n'; }
  std::string text() const { return text_.str(); }

 private:
  std::ostringstream text_;
};

std::string scene_key(const Measurement& m) {
  std::string grid = m.grid;
  std::replace(grid.begin(), grid.end(), '/', '_');
  return m.scene + '_' + grid;
}

}  // namespace

std::string snapshot_text(const BenchReport& report, const CoverageReport& coverage,
                          const SnapshotHeader& header, std::span<const ShapeRate> shapes) {
  std::ostringstream out;
  out << "# Measurement snapshot of chapter 10's report, " << size_name(report.size) << " setting\n"
      << "# machine: " << report.machine.cpu_model << ", " << report.machine.threads
      << " hardware threads\n"
      << "# compiler: " << report.machine.compiler << " (" << report.machine.build_type << ")\n"
      << "# commit: " << header.commit << '\n'
      << "# date: " << header.date << '\n'
      << "# peers: " << header.peers << '\n';
  if (!header.note.empty()) out << "# note: " << header.note << '\n';
  out << "key,value\n";
  KeyValues keys;
  for (const AlgorithmSummary& s : summarize(report.rows)) {
    keys.add(s.algorithm + ".chapter", s.chapter);
    keys.add(s.algorithm + ".threaded", s.threaded ? 1.0 : 0.0);
    keys.add(s.algorithm + ".mpix_per_s", s.mpix_per_s);
    keys.add(s.algorithm + ".large_mpix_per_s", s.large_mpix_per_s);
    keys.add(s.algorithm + ".tiny_tris_per_s", s.tiny_tris_per_s);
    keys.add(s.algorithm + ".mesh_tris_per_s", s.mesh_tris_per_s);
    keys.add(s.algorithm + ".ratio_to_ceiling", s.ratio_to_ceiling);
    keys.add(s.algorithm + ".error_rate", s.error_rate());
  }
  for (const Measurement& m : report.rows) {
    const std::string prefix = m.algorithm + '.' + scene_key(m) + '.';
    keys.add(prefix + "median_s", m.timing.seconds.median);
    keys.add(prefix + "tris_per_s", m.triangles_per_second());
    keys.add(prefix + "mpix_per_s", m.mpix_per_second());
    keys.add(prefix + "ratio_to_ceiling", m.ratio_to_ceiling());
  }
  for (const CoverageSummary& s : summarize_coverage(coverage.rows, report.rows)) {
    keys.add(s.algorithm + ".cost_vs_fastest", s.cost_vs_fastest);
    keys.add(s.algorithm + ".tris_per_s", s.tris_per_s);
    keys.add(s.algorithm + ".mean_error", s.mean_error);
    keys.add(s.algorithm + ".max_error", s.max_error);
  }
  if (!shapes.empty()) keys.add("blend2d_shapes.vectors", host_instruction_set());
  for (const ShapeRate& r : shapes) {
    keys.add(r.drawer + ".blend2d_" + std::to_string(r.box_side) + ".calls_per_ms",
             r.calls_per_ms());
  }
  return out.str() + keys.text();
}

std::string utc_date() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[16];
  std::strftime(text, sizeof text, "%Y-%m-%d", &utc);
  return text;
}

}  // namespace tri::ch10
