#include "chapters/10_speed_vs_error/summary.hpp"

#include <algorithm>
#include <map>

#include "measure/statistics.hpp"

namespace tri::ch10 {
namespace {

// The rows of one algorithm, collected while scanning.
struct Collected {
  AlgorithmSummary summary;
  std::vector<double> large, tiny, mesh, all_mpix, ratios;
};

}  // namespace

double AlgorithmSummary::error_rate() const noexcept {
  ErrorReport totals;
  totals.covered = covered;
  totals.missed = missed;
  totals.extra = extra;
  return totals.error_rate();
}

std::vector<AlgorithmSummary> summarize(std::span<const Measurement> rows) {
  std::vector<Collected> collected;
  std::map<std::string, std::size_t> index_of;
  for (const Measurement& m : rows) {
    auto [it, inserted] = index_of.try_emplace(m.algorithm, collected.size());
    if (inserted) {
      collected.emplace_back();
      AlgorithmSummary& s = collected.back().summary;
      s.algorithm = m.algorithm;
      s.chapter = m.chapter;
      s.rule = m.rule;
      s.threaded = m.threaded;
      s.precision_family = m.precision_family;
      s.precision_bits = m.precision_bits;
    }
    Collected& c = collected[it->second];
    AlgorithmSummary& s = c.summary;
    ++s.scenes;
    if (m.scene == "large") c.large.push_back(m.mpix_per_second());
    if (m.scene == "tiny") c.tiny.push_back(m.triangles_per_second());
    if (m.scene == "mesh") c.mesh.push_back(m.triangles_per_second());
    c.all_mpix.push_back(m.mpix_per_second());
    c.ratios.push_back(m.ratio_to_ceiling());
    s.covered += m.error.covered;
    s.missed += m.error.missed;
    s.extra += m.error.extra;
    if (m.mesh) {
      s.gaps += m.error.gaps;
      s.overdraw += m.error.overdraw;
    }
    s.order_dependent += m.error.order_dependent;
    s.outside_writes += m.error.outside_writes;
  }
  // [listing overall_means]
  std::vector<AlgorithmSummary> summaries;
  for (Collected& c : collected) {
    c.summary.large_mpix_per_s = geometric_mean(c.large);
    c.summary.tiny_tris_per_s = geometric_mean(c.tiny);
    c.summary.mesh_tris_per_s = geometric_mean(c.mesh);
    c.summary.mpix_per_s = geometric_mean(c.all_mpix);
    c.summary.ratio_to_ceiling = geometric_mean(c.ratios);
    summaries.push_back(std::move(c.summary));
  }
  return summaries;
  // [/listing]
}

std::vector<std::vector<std::size_t>> precision_families(
    std::span<const AlgorithmSummary> summaries) {
  std::map<std::pair<std::string, std::string>, std::vector<std::pair<int, std::size_t>>> members;
  std::vector<std::pair<std::string, std::string>> order;  // families in order of appearance
  for (std::size_t i = 0; i < summaries.size(); ++i) {
    const AlgorithmSummary& s = summaries[i];
    if (s.precision_family.empty()) continue;
    const auto key = std::make_pair(s.chapter, s.precision_family);
    if (!members.contains(key)) order.push_back(key);
    members[key].emplace_back(s.precision_bits, i);
  }
  std::vector<std::vector<std::size_t>> families;
  for (const auto& key : order) {
    auto& list = members[key];
    if (list.size() < 2) continue;
    std::sort(list.begin(), list.end());
    std::vector<std::size_t> family;
    for (const auto& [bits, index] : list) family.push_back(index);
    families.push_back(std::move(family));
  }
  return families;
}

}  // namespace tri::ch10
