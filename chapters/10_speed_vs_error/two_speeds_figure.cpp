#include "chapters/10_speed_vs_error/two_speeds_figure.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "chapters/10_speed_vs_error/figure_parts.hpp"
#include "common/printable_text.hpp"
#include "measure/plot/log_axis.hpp"
#include "measure/plot/plot_frame.hpp"
#include "measure/plot/svg_elements.hpp"

namespace tri::ch10 {
namespace {

namespace fp = figure_parts;

// The two vertex grids of every scene kind, as the snapshot's keys spell them.
constexpr const char* grids[] = {"integer", "1_256"};

// One panel: a log axis over whole decades, one bar per row from its left end.
struct Panel {
  PlotBox box;
  LogScale x;
};

Panel panel(double left, double right, double top, double bottom, std::span<const double> values) {
  DecadeRange decades = decades_covering(values);
  // Room for the shortest bar when it would barely leave the axis.
  if (*std::min_element(values.begin(), values.end()) < 3 * std::pow(10.0, decades.low)) {
    decades.low -= 1;
  }
  return {{left, right, top, bottom}, {decades.low, decades.high, left, right}};
}

void panel_frame(std::ostream& svg, const Panel& p, std::string_view title) {
  open_group(svg, {{"stroke", "#ddd"}});
  for (int k = p.x.low_decade; k <= p.x.high_decade; ++k) {
    const double at = p.x.position(std::pow(10.0, k));
    line(svg, at, p.box.top, at, p.box.bottom);
  }
  close_group(svg);
  line(svg, p.box.left, p.box.bottom, p.box.right, p.box.bottom, {{"stroke", "black"}});
  line(svg, p.box.left, p.box.top, p.box.left, p.box.bottom, {{"stroke", "black"}});
  x_decade_labels(svg, p.x, p.box, title);
}

void bar(std::ostream& svg, const Panel& p, double y, double height, double value,
         std::string_view fill) {
  element(svg, "rect",
          {{"x", p.box.left},
           {"y", y},
           {"width", p.x.position(value) - p.box.left},
           {"height", height},
           {"fill", std::string(fill)}});
}

}  // namespace

std::vector<std::string> two_speeds_algorithms() {
  return {"scanline_single_loop", "edge_function", "barycentric_double",
          "fast_hybrid",          "fast_batched",  "pixman_a1"};
}

TwoSpeeds two_speeds_of(const Snapshot& snapshot) {
  TwoSpeeds speeds;
  for (const std::string& algorithm : two_speeds_algorithms()) {
    const auto large = snapshot.number(algorithm + ".large_mpix_per_s");
    const auto tiny = snapshot.number(algorithm + ".tiny_tris_per_s");
    if (large && tiny) speeds.rows.push_back({algorithm, *large, *tiny});
  }
  if (speeds.rows.empty()) {
    throw std::runtime_error("the snapshot has none of the two-speeds figure's algorithms");
  }
  double product = 1;
  for (const char* grid : grids) {
    const std::string scene = speeds.rows.front().algorithm + ".large_" + grid + '.';
    const auto mpix = snapshot.number(scene + "mpix_per_s");
    const auto ratio = snapshot.number(scene + "ratio_to_ceiling");
    if (!mpix || !ratio || *ratio <= 0) {
      throw std::runtime_error("the snapshot has no ratio to the ceiling for " + scene);
    }
    product *= *mpix / *ratio;
  }
  speeds.ceiling_mpix_per_s = std::sqrt(product);
  return speeds;
}

SvgFigure two_speeds_figure(const Snapshot& snapshot) {
  const TwoSpeeds speeds = two_speeds_of(snapshot);
  std::vector<double> large{speeds.ceiling_mpix_per_s}, tiny;
  for (const auto& row : speeds.rows) {
    large.push_back(row.large_mpix_per_s);
    tiny.push_back(row.tiny_tris_per_s);
  }
  constexpr double width = 900, left = 20, row_height = 28, top = 118;
  const double bottom = top + row_height * static_cast<double>(speeds.rows.size());
  const Panel pixels = panel(170, 470, top, bottom, large);
  const Panel triangles = panel(630, 810, top, bottom, tiny);

  const double height = bottom + 122;
  std::ostringstream svg;
  open_plot(svg, width, height, left,
            "Two speeds: pixels written on large triangles, triangles drawn when they are tiny",
            "Chapter 10's quick run, geometric mean of each kind's integer and 1/256-grid scenes; "
            "from docs/measurements/report_quick.csv",
            "Measured on " + snapshot.header_text("machine") + " · " +
                snapshot.header_text("compiler") + " · " + snapshot.header_text("date") +
                " · commit " + snapshot.header_text("commit"));
  panel_frame(svg, pixels, "Mpixels/s, large triangles (log)");
  panel_frame(svg, triangles, "triangles/s, tiny triangles (log)");

  open_group(svg, {{"font-weight", "bold"}, {"text-anchor", "end"}});
  element(svg, "text", {{"x", pixels.box.right + 44}, {"y", top - 8}}, "Mpix/s");
  element(svg, "text", {{"x", pixels.box.right + 122}, {"y", top - 8}}, "of ceiling");
  element(svg, "text", {{"x", triangles.box.right + 80}, {"y", top - 8}}, "triangles/s");
  close_group(svg);
  for (std::size_t i = 0; i < speeds.rows.size(); ++i) {
    const auto& row = speeds.rows[i];
    const double y = top + row_height * static_cast<double>(i);
    const double text_y = y + row_height / 2 + 4;
    element(svg, "text", {{"x", left}, {"y", text_y}}, escape_xml(row.algorithm));
    bar(svg, pixels, y + 5, row_height - 10, row.large_mpix_per_s, fp::blue);
    bar(svg, triangles, y + 5, row_height - 10, row.tiny_tris_per_s, fp::orange);
    open_group(svg, {{"text-anchor", "end"}});
    element(svg, "text", {{"x", pixels.box.right + 44}, {"y", text_y}},
            fp::about_three_digits(row.large_mpix_per_s));
    element(svg, "text", {{"x", pixels.box.right + 122}, {"y", text_y}},
            fp::about_three_digits(100 * row.large_mpix_per_s / speeds.ceiling_mpix_per_s) + "%");
    element(svg, "text", {{"x", triangles.box.right + 80}, {"y", text_y}},
            fp::fixed(row.tiny_tris_per_s / 1e6, 2) + " M");
    close_group(svg);
  }
  const double ceiling_x = pixels.x.position(speeds.ceiling_mpix_per_s);
  line(svg, ceiling_x, top - 18, ceiling_x, bottom,
       {{"stroke", fp::vermillion}, {"stroke-width", 2.0}, {"stroke-dasharray", "5 3"}});
  element(svg, "text",
          {{"x", ceiling_x - 5}, {"y", top - 8}, {"text-anchor", "end"}, {"fill", fp::vermillion}},
          "write ceiling " + fp::about_three_digits(speeds.ceiling_mpix_per_s) + " Mpix/s");

  double y = bottom + 58;
  fp::legend_swatch(svg, left, y, fp::blue,
                    "Mpixels/s: pixels written per second, where filling dominates");
  fp::legend_swatch(svg, left + 450, y, fp::orange,
                    "triangles/s: where each triangle's setup dominates");
  y += 20;
  fp::legend_dash(svg, left, y, fp::vermillion,
                  "write ceiling: the faster of memset and 16-byte stores over the canvas, "
                  "timed in the same run; no 4-byte-a-pixel fill passes it");
  y += 20;
  element(svg, "text", {{"x", left}, {"y", y + 10}, {"fill", "#555"}},
          "The ceiling bounds Mpixels/s only: no line is drawn beside triangles/s.");
  svg << "</svg>\n";
  return {"10_two_speeds", svg.str()};
}

}  // namespace tri::ch10
