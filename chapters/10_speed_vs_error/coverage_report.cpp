#include "chapters/10_speed_vs_error/coverage_report.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

#include "chapters/10_speed_vs_error/plot_svg.hpp"
#include "chapters/10_speed_vs_error/report_csv.hpp"
#include "chapters/10_speed_vs_error/report_markdown.hpp"
#include "measure/plot/log_axis.hpp"
#include "measure/plot/plot_frame.hpp"
#include "measure/plot/svg_elements.hpp"
#include "measure/statistics.hpp"

namespace tri::ch10 {
namespace {

using SceneKey = std::pair<std::string, std::string>;  // scene kind, grid

SceneKey key_of(const auto& row) {
  return {row.scene, row.grid};
}

// Chapter 08's fastest single-thread time per scene: what "cost per triangle" is compared with.
std::map<SceneKey, double> fastest_exact_seconds(std::span<const Measurement> triangle_rows) {
  std::map<SceneKey, double> fastest;
  for (const Measurement& m : triangle_rows) {
    if (m.chapter != "08_fast_exact" || m.threaded || !(m.timing.seconds.median > 0)) continue;
    const auto [it, added] = fastest.try_emplace(key_of(m), m.timing.seconds.median);
    if (!added) it->second = std::min(it->second, m.timing.seconds.median);
  }
  return fastest;
}

// A row's speed on each scene, by algorithm name.
std::map<SceneKey, double> speeds_of(std::span<const CoverageMeasurement> rows,
                                     const std::string& algorithm) {
  std::map<SceneKey, double> speeds;
  for (const CoverageMeasurement& m : rows) {
    if (m.algorithm == algorithm) speeds[key_of(m)] = m.triangles_per_second();
  }
  return speeds;
}

// The least-squares slope of log(mean error) against log(n) over the regular grids.
double grid_error_slope(std::span<const CoverageSummary> summaries) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int count = 0;
  for (const CoverageSummary& s : summaries) {
    if (!s.algorithm.starts_with("samples_grid_") || !(s.mean_error > 0)) continue;
    const double x = std::log(std::sqrt(static_cast<double>(s.samples)));
    const double y = std::log(s.mean_error);
    sx += x, sy += y, sxx += x * x, sxy += x * y, ++count;
  }
  if (count < 2) return std::numeric_limits<double>::quiet_NaN();
  return (count * sxy - sx * sy) / (count * sxx - sx * sx);
}

}  // namespace

std::vector<CoverageSummary> summarize_coverage(std::span<const CoverageMeasurement> rows,
                                                std::span<const Measurement> triangle_rows) {
  const auto fastest = fastest_exact_seconds(triangle_rows);
  struct Collected {
    CoverageSummary summary;
    std::vector<double> speeds, costs;
    double error_sum = 0;
    std::uint64_t pixels = 0;
  };
  std::vector<Collected> collected;
  for (const CoverageMeasurement& m : rows) {
    auto it = std::find_if(collected.begin(), collected.end(),
                           [&](const Collected& c) { return c.summary.algorithm == m.algorithm; });
    if (it == collected.end()) {
      collected.push_back({{m.algorithm, m.chapter, m.rule, m.samples}, {}, {}, 0, 0});
      it = collected.end() - 1;
    }
    CoverageSummary& s = it->summary;
    ++s.scenes;
    it->speeds.push_back(m.triangles_per_second());
    if (const auto f = fastest.find(key_of(m)); f != fastest.end()) {
      it->costs.push_back(m.timing.seconds.median / f->second);
    }
    it->error_sum += m.error.mean * static_cast<double>(m.error.pixels);
    it->pixels += m.error.pixels;
    s.max_error = std::max(s.max_error, m.error.max);
    s.max_units = std::max(s.max_units, m.error.max_units);
    if (m.mesh) s.seam_max = std::max(s.seam_max, m.error.composed_max);
  }
  std::vector<CoverageSummary> summaries;
  for (Collected& c : collected) {
    c.summary.tris_per_s = geometric_mean(c.speeds);
    c.summary.cost_vs_fastest = geometric_mean(c.costs);
    c.summary.mean_error = c.pixels == 0 ? 0 : c.error_sum / static_cast<double>(c.pixels);
    summaries.push_back(c.summary);
  }
  return summaries;
}

std::string coverage_csv(std::span<const CoverageMeasurement> rows) {
  constexpr std::string_view header =
      "algorithm,chapter,rule,samples,scene,grid,mesh,width,height,triangles,touched_pixels,"
      "median_seconds,min_seconds,max_seconds,repetitions,samples_timed,tris_per_s,"
      "error_triangles,rejected,error_pixels,mean_error,rms_error,max_error,max_units,"
      "composed_pixels,composed_mean,composed_max,composed_off_pixels";
  return csv_table(header, rows, [](const CoverageMeasurement& m) {
    return std::tuple(
        m.algorithm, m.chapter, m.rule, m.samples, m.scene, m.grid, m.mesh ? 1 : 0, m.width,
        m.height, m.triangles, m.touched_pixels, seconds_columns(m.timing), m.timing.repetitions,
        m.timing.samples, format_number(m.triangles_per_second(), 6), m.error.triangles,
        m.error.rejected, m.error.pixels, format_number(m.error.mean, 6),
        format_number(m.error.rms, 6), format_number(m.error.max, 6), m.error.max_units,
        m.error.composed_pixels, format_number(m.error.composed_mean, 6),
        format_number(m.error.composed_max, 6), m.error.composed_off_pixels);
  });
}

std::string coverage_markdown(std::span<const CoverageSummary> summaries,
                              std::span<const CoverageMeasurement> rows,
                              const std::string& peer_status) {
  if (summaries.empty()) return {};
  std::ostringstream md;
  md << "\n## Coverage: rule area\n\n"
     << "Chapter 09's coverage algorithms (and the anti-aliasing peers: " << peer_status
     << ") drew the same scenes, adding each triangle's coverage (the fraction of each pixel "
        "square it covers) to a canvas of floats, timed like the algorithms above. *tris/s* is "
        "the geometric mean over the scenes; *cost* is the time per scene divided by chapter "
        "08's fastest single-thread time on that scene (geometric mean). The error compares each "
        "triangle drawn alone with chapter 09's exact area over every pixel either touches: "
        "*mean* and *max* of |coverage − exact|, *16-bit* the largest difference of the "
        "`raster --coverage` output (round(65535 × coverage)); *seam* is the largest error of the "
        "whole mesh (mesh and fan scenes) against the exact coverages summed. Every measurement "
        "is in `10_coverage.csv`; the plot is `10_coverage_speed_vs_error.svg`.\n\n"
     << "| algorithm | chapter | samples | tris/s | cost | mean error | max error | 16-bit | "
        "seam |\n"
     << "|---|---|--:|--:|--:|--:|--:|--:|--:|\n";
  for (const CoverageSummary& s : summaries) {
    md << "| `" << s.algorithm << "` | " << s.chapter << " | "
       << (s.samples == 0 ? std::string("area") : std::to_string(s.samples)) << " | "
       << human_rate(s.tris_per_s) << " | "
       << (s.cost_vs_fastest > 0 ? format_number(s.cost_vs_fastest, 3) + "×" : "–") << " | "
       << format_number(s.mean_error, 3) << " | " << format_number(s.max_error, 3) << " | "
       << s.max_units << " | " << format_number(s.seam_max, 3) << " |\n";
  }
  const double slope = grid_error_slope(summaries);
  if (std::isfinite(slope)) {
    md << "\nOn the regular grids the mean error falls as n^" << format_number(slope, 3)
       << " for n × n samples (least squares over the grids measured; 1/n would be n^−1).";
  }
  const auto exact = speeds_of(rows, "area_cells");
  for (const CoverageSummary& s : summaries) {
    if (s.chapter != "external" || exact.empty()) continue;
    std::vector<double> ratios;
    double slowest = std::numeric_limits<double>::infinity();
    for (const auto& [scene, speed] : speeds_of(rows, s.algorithm)) {
      if (const auto e = exact.find(scene); e != exact.end() && speed > 0) {
        ratios.push_back(e->second / speed);
        slowest = std::min(slowest, e->second / speed);
      }
    }
    if (ratios.empty()) continue;
    md << "\n`area_cells` against `" << s.algorithm
       << "`: " << format_number(geometric_mean(ratios), 3) << "× its speed (geometric mean over "
       << ratios.size() << " scenes; " << format_number(slowest, 3)
       << "× on the least favourable).";
  }
  md << "\n";
  return md.str();
}

// Errors below this are a float's rounding of the exact area: drawn at the axis's "exact" floor.
constexpr double exact_below = 1e-6;

std::string coverage_svg(std::span<const CoverageSummary> summaries, const std::string& subtitle) {
  const double width = 900, height = 600, left = 90, right = 860, top = 80, bottom = 530;
  const double floor_gap = 70;  // between the "exact" floor and the first decade
  std::vector<double> errors, speeds;
  for (const CoverageSummary& s : summaries) {
    if (s.mean_error >= exact_below) errors.push_back(s.mean_error);
    speeds.push_back(s.tris_per_s);
  }
  const DecadeRange xd = decades_covering(errors), yd = decades_covering(speeds);
  const ErrorAxis x{{xd.low, xd.high, left + floor_gap, right}, left + floor_gap / 2};
  const auto x_of = [&](double error) { return x.position(error >= exact_below ? error : 0); };
  const LogScale y{yd.low, yd.high, bottom, top};
  const PlotBox box{left, right, top, bottom};
  std::ostringstream svg;
  open_plot(svg, width, height, left,
            "Anti-aliasing: speed against error, every coverage algorithm", subtitle,
            "y: triangles per second, geometric mean over all scenes; x: mean |coverage − exact "
            "area| per touched pixel");
  log_grid_and_axes(svg, x.scale, y, box);
  line(svg, x.zero_position, top, x.zero_position, bottom,
       {{"stroke", "#999"}, {"stroke-dasharray", "2 3"}});
  element(svg, "text",
          {{"x", x.zero_position},
           {"y", bottom + 16},
           {"font-weight", "bold"},
           {"text-anchor", "middle"}},
          "exact");
  x_decade_labels(svg, x.scale, box,
                  "mean error per touched pixel (log; below 10⁻⁶, a float's rounding, drawn at "
                  "\"exact\")");
  y_decade_labels(svg, y, box, power_of_ten_label, "triangles per second (log)");

  // The guide: from one sample per pixel, error falling as 1/n while the cost grows as n².
  const auto one = std::find_if(summaries.begin(), summaries.end(),
                                [](const CoverageSummary& s) { return s.samples == 1; });
  if (one != summaries.end() && one->mean_error > 0 && one->tris_per_s > 0) {
    std::string points;
    for (int n = 1; n <= 16; n *= 2) {
      points += (n == 1 ? "" : " ") + svg_number(x_of(one->mean_error / n)) + ',' +
                svg_number(y.position(one->tris_per_s / (n * n)));
    }
    element(
        svg, "polyline",
        {{"points", points}, {"fill", "none"}, {"stroke", "#999"}, {"stroke-dasharray", "5 4"}});
  }
  // The sample counts of one pattern family, joined from the fewest samples to the most; the
  // grid's labels go left of its points and the others' right, so the two curves stay readable.
  const std::pair<const char*, const char*> families[] = {{"samples_grid_", "#4e79a7"},
                                                          {"samples_standard_", "#f28e2b"}};
  for (const auto& [prefix, colour] : families) {
    std::vector<const CoverageSummary*> members;
    for (const CoverageSummary& s : summaries) {
      if (s.algorithm.starts_with(prefix)) members.push_back(&s);
    }
    std::sort(members.begin(), members.end(),
              [](const auto* a, const auto* b) { return a->samples < b->samples; });
    std::string points;
    for (const CoverageSummary* s : members) {
      points += (points.empty() ? "" : " ") + svg_number(x_of(s->mean_error)) + ',' +
                svg_number(y.position(s->tris_per_s));
    }
    if (members.size() > 1) {
      element(svg, "polyline", {{"points", points}, {"fill", "none"}, {"stroke", colour}});
    }
  }
  std::vector<std::pair<double, double>> labelled;  // points already labelled
  double floor_labels_end = 0;  // right end of the labels of points at the exact floor
  for (std::size_t i = 0; i < summaries.size(); ++i) {
    const CoverageSummary& s = summaries[i];
    const bool grid = s.algorithm.starts_with("samples_grid_");
    const char* colour = s.chapter == "external"                        ? "#e15759"
                         : grid                                         ? "#4e79a7"
                         : s.algorithm.starts_with("samples_standard_") ? "#f28e2b"
                                                                        : "#59a14f";
    const double px = x_of(s.mean_error), py = y.position(s.tris_per_s);
    element(svg, "circle", {{"cx", px}, {"cy", py}, {"r", "4.5"}, {"fill", colour}},
            "<title>" + escape_xml(s.algorithm) + "</title>");
    // Algorithms at the same point (area_cells and area_cells_over) share one label.
    if (std::find_if(labelled.begin(), labelled.end(), [&](const auto& p) {
          return std::abs(p.first - px) < 3 && std::abs(p.second - py) < 3;
        }) != labelled.end())
      continue;
    labelled.emplace_back(px, py);
    std::string text = s.algorithm;
    for (std::size_t j = i + 1; j < summaries.size(); ++j) {
      if (std::abs(x_of(summaries[j].mean_error) - px) < 3 &&
          std::abs(y.position(summaries[j].tris_per_s) - py) < 3)
        text += ", " + summaries[j].algorithm;
    }
    // Left of the point for the grids, and for any label that would leave the image.
    if (grid || px + 8 + 6.4 * static_cast<double>(text.size()) > width) {
      element(svg, "text", {{"x", px - 8}, {"y", py + 4}, {"text-anchor", "end"}},
              escape_xml(text));
    } else {
      element(svg, "text", {{"x", px + 8}, {"y", py + 4}}, escape_xml(text));
      if (px == x.zero_position) {
        floor_labels_end =
            std::max(floor_labels_end, px + 8 + 6.4 * static_cast<double>(text.size()));
      }
    }
  }
  // The legend, in the plot's empty upper left (fast and exact: only the cell method gets near),
  // right of the labels of the points at the exact floor, so that it hides none of them.
  const double legend_x = std::max(left + floor_gap, floor_labels_end + 12);
  const std::pair<const char*, const char*> legend[] = {
      {"#4e79a7", "regular n × n grid (1 to 256 samples)"},
      {"#f28e2b", "Vulkan standard pattern (2 to 16 samples)"},
      {"#59a14f", "exact area by cells (chapter 09)"},
      {"#e15759", "external peer"}};
  double ly = top + 24;
  element(svg, "rect",
          {{"x", legend_x},
           {"y", ly - 16},
           {"width", "290"},
           {"height", "100"},
           {"fill", "white"},
           {"stroke", "#ccc"}});
  for (const auto& [colour, text] : legend) {
    element(svg, "circle", {{"cx", legend_x + 14}, {"cy", ly - 4}, {"r", "4.5"}, {"fill", colour}});
    element(svg, "text", {{"x", legend_x + 26}, {"y", ly}}, text);
    ly += 18;
  }
  line(svg, legend_x + 6, ly - 4, legend_x + 22, ly - 4,
       {{"stroke", "#999"}, {"stroke-dasharray", "5 4"}});
  element(svg, "text", {{"x", legend_x + 26}, {"y", ly}}, "error ∝ 1/n, cost ∝ n² (guide)");
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace tri::ch10
