#include "chapters/10_speed_vs_error/scaling_report.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <vector>

#include "chapters/10_speed_vs_error/plot_svg.hpp"
#include "chapters/10_speed_vs_error/report_csv.hpp"
#include "chapters/10_speed_vs_error/report_markdown.hpp"
#include "common/printable_text.hpp"
#include "measure/plot/log_axis.hpp"
#include "measure/plot/plot_frame.hpp"
#include "measure/plot/svg_elements.hpp"

namespace tri::ch10 {
namespace {

// Bytes in the largest binary unit that keeps the number at 1 or more: "812 KiB", "1.45 MiB".
std::string human_bytes(std::uint64_t bytes) {
  const char* units[] = {"bytes", "KiB", "MiB", "GiB"};
  double value = static_cast<double>(bytes);
  std::size_t unit = 0;
  while (value >= 1024 && unit + 1 < std::size(units)) {
    value /= 1024;
    ++unit;
  }
  return format_mpix(value) + " " + units[unit];
}

// Whole milliseconds from 100 up ("1239 ms"), else 3 significant digits ("0.0828 ms").
std::string milliseconds(double seconds) {
  return format_mpix(seconds * 1e3) + " ms";
}

// The names in the order they first appear.
template <class Field>
std::vector<std::string> in_order(std::span<const ScalingPoint> points, std::string_view sweep,
                                  Field field) {
  std::vector<std::string> names;
  for (const ScalingPoint& p : points) {
    if (p.sweep == sweep && std::find(names.begin(), names.end(), p.*field) == names.end())
      names.push_back(p.*field);
  }
  return names;
}

// One sweep's table: a row per scene and size, a column per drawer.
void sweep_table(std::ostream& md, std::span<const ScalingPoint> points, std::string_view sweep) {
  const std::vector<std::string> drawers = in_order(points, sweep, &ScalingPoint::drawer);
  md << (sweep == "canvas" ? "| canvas | triangles |" : "| scene | triangles |")
     << " triangle data |";
  for (const std::string& d : drawers) md << " `" << d << "` |";
  md << "\n|---|--:|--:|";
  for (std::size_t i = 0; i < drawers.size(); ++i) md << "--:|";
  md << "\n";
  std::vector<const ScalingPoint*> skipped;
  for (std::size_t i = 0; i < points.size();) {
    const ScalingPoint& first = points[i];
    if (first.sweep != sweep) {
      ++i;
      continue;
    }
    md << "| "
       << (sweep == "canvas" ? std::to_string(first.side) + "×" + std::to_string(first.side)
                             : first.scene)
       << " | " << first.triangles << " | " << human_bytes(first.scene_bytes) << " |";
    std::map<std::string, const ScalingPoint*> by_drawer;
    for (; i < points.size() && points[i].sweep == sweep && points[i].scene == first.scene &&
           points[i].side == first.side && points[i].triangles == first.triangles;
         ++i) {
      by_drawer[points[i].drawer] = &points[i];
    }
    for (const std::string& d : drawers) {
      const auto found = by_drawer.find(d);
      if (found == by_drawer.end()) {
        md << " |";
      } else if (!found->second->measured) {
        md << " – |";
        skipped.push_back(found->second);
      } else {
        md << " " << milliseconds(found->second->timing.seconds.median) << " · +"
           << human_bytes(found->second->peak_bytes) << " |";
      }
    }
    md << "\n";
  }
  md << "\n";
  for (const ScalingPoint* p : skipped) {
    md << "- `" << p->drawer << "`, " << p->scene << ", " << p->triangles << " triangles on "
       << p->side << "×" << p->side << ": not measured, " << p->not_measured_because << "\n";
  }
  if (!skipped.empty()) md << "\n";
  md << "Growth from the first to the last measured point, as time ∝ "
     << (sweep == "canvas" ? "pixels" : "triangles") << "^k:";
  bool first_item = true;
  for (const std::string& scene : in_order(points, sweep, &ScalingPoint::scene)) {
    for (const std::string& d : drawers) {
      const double k = growth_exponent(points, sweep, scene, d);
      if (k == 0) continue;
      md << (first_item ? " " : "; ") << "`" << d << "` " << (sweep == "canvas" ? "" : scene + " ")
         << "k = " << format_number(k, 2);
      first_item = false;
    }
  }
  md << ".\n\n";
}

}  // namespace

std::string scaling_csv(std::span<const ScalingPoint> points) {
  constexpr std::string_view header =
      "sweep,drawer,chapter,scene,side,triangles,scene_bytes,measured,seconds_median,"
      "seconds_min,seconds_max,repetitions,samples,peak_bytes,not_measured_because";
  return csv_table(header, points, [](const ScalingPoint& p) {
    return std::tuple(p.sweep, p.drawer, p.chapter, p.scene, p.side, p.triangles, p.scene_bytes,
                      p.measured ? 1 : 0, seconds_columns(p.timing), p.timing.repetitions,
                      p.timing.samples, p.peak_bytes, quoted_text(p.not_measured_because));
  });
}

double growth_exponent(std::span<const ScalingPoint> points, std::string_view sweep,
                       std::string_view scene, std::string_view drawer) {
  const ScalingPoint* first = nullptr;
  const ScalingPoint* last = nullptr;
  for (const ScalingPoint& p : points) {
    if (p.sweep != sweep || p.scene != scene || p.drawer != drawer || !p.measured ||
        !(p.timing.seconds.median > 0))
      continue;
    if (!first || swept_quantity(p) < swept_quantity(*first)) first = &p;
    if (!last || swept_quantity(p) > swept_quantity(*last)) last = &p;
  }
  if (!first || swept_quantity(*last) <= swept_quantity(*first)) return 0;
  return std::log(last->timing.seconds.median / first->timing.seconds.median) /
         std::log(swept_quantity(*last) / swept_quantity(*first));
}

std::string scaling_markdown(std::span<const ScalingPoint> points) {
  if (points.empty()) return {};
  std::ostringstream md;
  md << "## How cost grows\n\n"
     << "Each cell is the median time of one frame and, after it, the most memory the draw "
        "added at once (its canvas, its own copies of the triangles), measured in a child "
        "process of its own; the triangle data, given to every drawer, is counted apart. "
        "`write_ceiling` is one fill of every pixel of the canvas, the faster of memset and "
        "vector stores. Vertices are on the 1/256 grid.\n\n"
     << "### Time per frame against the number of triangles\n\n";
  sweep_table(md, points, "triangles");
  md << "### Time per frame against the canvas (large triangles)\n\n";
  sweep_table(md, points, "canvas");
  return md.str();
}

std::string scaling_svg(std::span<const ScalingPoint> points, std::string_view sweep,
                        const std::string& subtitle) {
  const double width = 900, height = 580, left = 90, right = 860, top = 80, bottom = 500;
  std::vector<const ScalingPoint*> measured;
  std::vector<double> xs, ys;
  for (const ScalingPoint& p : points) {
    if (p.sweep != sweep || !p.measured || !(p.timing.seconds.median > 0)) continue;
    measured.push_back(&p);
    xs.push_back(swept_quantity(p));
    ys.push_back(p.timing.seconds.median * 1e3);
  }
  const DecadeRange xd = decades_covering(xs), yd = decades_covering(ys);
  const LogScale x{xd.low, xd.high, left, right}, y{yd.low, yd.high, bottom, top};
  const bool canvas = sweep == "canvas";
  const PlotBox box{left, right, top, bottom};
  std::ostringstream svg;
  open_plot(svg, width, height, left,
            canvas ? "How cost grows with the canvas: large triangles, 256² and up"
                   : "How cost grows with the triangles: tiny and mixed scenes",
            subtitle,
            "y: median milliseconds per frame; dotted grey: time in proportion to x (slope 1)");
  log_grid_and_axes(svg, x, y, box);
  x_decade_labels(svg, x, box,
                  canvas ? "pixels of the canvas (log): 256² is 6.6·10⁴, 16384² is 2.7·10⁸"
                         : "triangles per frame (log)");
  y_decade_labels(svg, y, box, decade_label, "milliseconds per frame (log)");

  // One colour per drawer, one dash per scene; a line through each drawer's points of a scene.
  const std::vector<std::string> drawers = in_order(points, sweep, &ScalingPoint::drawer);
  const std::vector<std::string> scenes = in_order(points, sweep, &ScalingPoint::scene);
  // The write ceiling in grey; every drawer else a colour of its own, in order.
  static constexpr const char* palette[] = {"#4e79a7", "#e15759", "#f28e2b", "#59a14f",
                                            "#b07aa1", "#76b7b2", "#edc948", "#9c755f"};
  std::map<std::string, const char*> colours;
  std::size_t coloured = 0;
  for (const ScalingPoint& p : points) {
    if (p.sweep != sweep || colours.contains(p.drawer)) continue;
    colours[p.drawer] =
        p.chapter == "ceiling" ? "#555555" : palette[coloured++ % std::size(palette)];
  }
  const auto colour_of = [&](const std::string& drawer) { return colours.at(drawer); };
  const auto dash_of = [&](const std::string& scene) {
    return scene == scenes.front() ? "none" : "6 4";
  };
  // The guide: slope 1 through the first drawer's smallest point.
  if (!measured.empty()) {
    const ScalingPoint& p = *measured.front();
    const double x0 = swept_quantity(p), y0 = p.timing.seconds.median * 1e3;
    const double x1 = std::pow(10.0, xd.high);
    element(
        svg, "polyline",
        {{"points", svg_number(x.position(x0)) + ',' + svg_number(y.position(y0)) + ' ' +
                        svg_number(x.position(x1)) + ',' + svg_number(y.position(y0 * x1 / x0))},
         {"fill", "none"},
         {"stroke", "#999"},
         {"stroke-dasharray", "2 4"}});
  }
  for (const std::string& drawer : drawers) {
    for (const std::string& scene : scenes) {
      std::string polyline;
      for (const ScalingPoint* p : measured) {
        if (p->drawer != drawer || p->scene != scene) continue;
        const double px = x.position(swept_quantity(*p)),
                     py = y.position(p->timing.seconds.median * 1e3);
        polyline += (polyline.empty() ? "" : " ") + svg_number(px) + ',' + svg_number(py);
        element(
            svg, "circle", {{"cx", px}, {"cy", py}, {"r", "3.5"}, {"fill", colour_of(drawer)}},
            "<title>" +
                escape_xml(drawer + ", " + scene + ": " + milliseconds(p->timing.seconds.median) +
                           " per frame, +" + human_bytes(p->peak_bytes)) +
                "</title>");
      }
      if (polyline.find(' ') != std::string::npos) {
        element(svg, "polyline",
                {{"points", polyline},
                 {"fill", "none"},
                 {"stroke", colour_of(drawer)},
                 {"stroke-dasharray", dash_of(scene)}});
      }
    }
  }
  // The legend, top left inside the plot (the lines start low there and rise to the right).
  const double lx = left + 12, row = 17;
  double ly = top + 20;
  const double rows = static_cast<double>(drawers.size() + (scenes.size() > 1 ? scenes.size() : 0));
  element(svg, "rect",
          {{"x", lx - 6},
           {"y", ly - 14},
           {"width", "250"},
           {"height", rows * row + 8},
           {"fill", "white"},
           {"stroke", "#ccc"}});
  for (const std::string& drawer : drawers) {
    line(svg, lx, ly - 4, lx + 24, ly - 4, {{"stroke", colour_of(drawer)}, {"stroke-width", "2"}});
    element(svg, "text", {{"x", lx + 32}, {"y", ly}}, escape_xml(drawer));
    ly += row;
  }
  if (scenes.size() > 1) {
    for (const std::string& scene : scenes) {
      line(svg, lx, ly - 4, lx + 24, ly - 4,
           {{"stroke", "#333"}, {"stroke-dasharray", dash_of(scene)}});
      element(svg, "text", {{"x", lx + 32}, {"y", ly}}, escape_xml(scene + " triangles"));
      ly += row;
    }
  }
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace tri::ch10
