#include "chapters/10_speed_vs_error/plot_svg.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <map>
#include <ostream>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "chapters/10_speed_vs_error/report_csv.hpp"
#include "measure/plot/plot_frame.hpp"
#include "measure/plot/svg_elements.hpp"

namespace tri::ch10 {
namespace {

// Ten colours that stay apart for colour-blind readers (Tableau 10), one per chapter.
constexpr std::array<const char*, 10> palette{"#4e79a7", "#f28e2b", "#e15759", "#76b7b2",
                                              "#59a14f", "#edc948", "#b07aa1", "#ff9da7",
                                              "#9c755f", "#bab0ac"};

constexpr double label_height = 12;       // px between label baselines
constexpr double label_char_width = 6.4;  // px per character at font-size 11

struct Box {
  double left = 0, top = 0, right = 0, bottom = 0;
  bool overlaps(const Box& other) const {
    return left < other.right && other.left < right && top < other.bottom && other.top < bottom;
  }
};

struct Label {
  double point_x = 0, point_y = 0;
  double x = 0, y = 0;  // baseline start (or end, when anchored at the end)
  double width = 0;
  bool anchor_end = false;
  std::string text;
  Box box() const {
    const double left = anchor_end ? x - width : x;
    return {left, y - 9, left + width, y + 2};
  }
};

// Each label tries spots beside its point (right, then left), then further up and down, and
// takes the first that overlaps no placed label, no point and stays on the plot: greedy, top
// to bottom, which is enough for a few dozen names.
void place_labels(std::vector<Label>& labels, const PlotLayout& layout) {
  std::vector<Box> taken;
  for (const Label& l : labels) {
    taken.push_back({l.point_x - 6, l.point_y - 6, l.point_x + 6, l.point_y + 6});
  }
  const Box plot{layout.left, layout.top - 10, layout.right + 25, layout.bottom};
  const auto inside = [&](const Box& b) {
    return b.left >= plot.left && b.right <= plot.right && b.top >= plot.top &&
           b.bottom <= plot.bottom;
  };
  std::vector<std::size_t> order(labels.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return labels[a].point_y < labels[b].point_y; });
  for (const std::size_t i : order) {
    Label& l = labels[i];
    l.width = label_char_width * static_cast<double>(l.text.size());
    bool placed = false;
    for (int step = 0; step <= 8 && !placed; ++step) {
      for (const double dy : {step * label_height, -step * label_height}) {
        for (const bool end : {false, true}) {
          l.anchor_end = end;
          l.x = end ? l.point_x - 8 : l.point_x + 8;
          l.y = l.point_y + 4 + dy;
          const Box box = l.box();
          placed = inside(box) && std::none_of(taken.begin(), taken.end(),
                                               [&](const Box& t) { return t.overlaps(box); });
          if (placed) break;
        }
        if (placed || step == 0) break;  // step 0 has a single offset
      }
    }
    if (!placed) {  // crowded: right of the point, overlapping
      l.anchor_end = false;
      l.x = l.point_x + 8;
      l.y = l.point_y + 4;
    }
    taken.push_back(l.box());
  }
}

// One colour per chapter, in the order the chapters first appear.
struct ChapterColours {
  explicit ChapterColours(std::span<const AlgorithmSummary> summaries) {
    for (const AlgorithmSummary& s : summaries) {
      if (index.try_emplace(s.chapter, chapters.size()).second) chapters.push_back(s.chapter);
    }
  }
  const char* of(const std::string& chapter) const {
    return palette[index.at(chapter) % palette.size()];
  }
  std::map<std::string, std::size_t> index;
  std::vector<std::string> chapters;
};

// The document's opening tag, white background and the three lines of title.
void write_header(std::ostream& svg, const BenchReport& report, const PlotLayout& layout) {
  std::ostringstream setting;
  setting << size_name(report.size) << " setting, " << report.width << "×" << report.height
          << " canvas, " << report.machine.cpu_model << " (" << report.machine.threads
          << " threads), " << report.machine.compiler << ", " << report.machine.build_type;
  open_plot(svg, layout.width, layout.height, layout.left,
            "Speed against error, every registered algorithm", setting.str(),
            "y: pixels written per second (Mpix/s), geometric mean over all scenes; x: (missed + "
            "extra) per covered pixel over all scenes");
}

// Light lines at every decade of both axes, and a dashed one at "exact".
void write_grid(std::ostream& svg, const ErrorAxis& x_axis, const LogScale& y_axis,
                const PlotLayout& layout) {
  open_group(svg, {{"stroke", "#ddd"}, {"stroke-width", "1"}});
  for (int k = x_axis.scale.low_decade; k <= x_axis.scale.high_decade; ++k) {
    const double x = x_axis.scale.position(std::pow(10.0, k));
    line(svg, x, layout.top, x, layout.bottom);
  }
  for (int k = y_axis.low_decade; k <= y_axis.high_decade; ++k) {
    const double y = y_axis.position(std::pow(10.0, k));
    line(svg, layout.left, y, layout.right, y);
  }
  line(svg, x_axis.zero_position, layout.top, x_axis.zero_position, layout.bottom,
       {{"stroke-dasharray", "2 3"}});
  close_group(svg);
}

// The two axes, and the break between "exact" and the first decade: log 0 is not on the scale.
void write_axes(std::ostream& svg, const PlotLayout& layout) {
  open_group(svg, {{"stroke", "black"}, {"stroke-width", "1"}, {"fill", "none"}});
  line(svg, layout.left, layout.bottom, layout.right, layout.bottom);
  line(svg, layout.left, layout.top, layout.left, layout.bottom);
  const double break_x = layout.left + 0.75 * layout.floor_gap;
  for (const double dx : {-3.0, 3.0}) {
    line(svg, break_x + dx - 3, layout.bottom + 5, break_x + dx + 3, layout.bottom - 5);
  }
  close_group(svg);
}

void write_x_labels(std::ostream& svg, const ErrorAxis& x_axis, const PlotLayout& layout) {
  open_group(svg, {{"text-anchor", "middle"}});
  element(svg, "text",
          {{"x", x_axis.zero_position}, {"y", layout.bottom + 16}, {"font-weight", "bold"}},
          "exact");
  for (int k = x_axis.scale.low_decade; k <= x_axis.scale.high_decade; ++k) {
    element(svg, "text",
            {{"x", x_axis.scale.position(std::pow(10.0, k))}, {"y", layout.bottom + 16}},
            power_of_ten_label(k));
  }
  element(svg, "text",
          {{"x", (layout.left + layout.right) / 2}, {"y", layout.bottom + 38}, {"font-size", "13"}},
          "error: wrong pixels per covered pixel (log; 0 drawn at \"exact\")");
  close_group(svg);
}

void write_y_labels(std::ostream& svg, const LogScale& y_axis, const PlotLayout& layout) {
  open_group(svg, {{"text-anchor", "end"}});
  for (int k = y_axis.low_decade; k <= y_axis.high_decade; ++k) {
    element(svg, "text", {{"x", layout.left - 6}, {"y", y_axis.position(std::pow(10.0, k)) + 4}},
            decade_label(k));
  }
  const double middle_y = (layout.top + layout.bottom) / 2;
  element(svg, "text",
          {{"x", "0"},
           {"y", "0"},
           {"font-size", "13"},
           {"text-anchor", "middle"},
           {"transform", "translate(" + svg_number(layout.left - 58) + ' ' + svg_number(middle_y) +
                             ") rotate(-90)"}},
          "speed: Mpixels written per second (log)");
  close_group(svg);
}

// The write ceilings: one thread, and the threaded one when it is higher and used.
void write_ceilings(std::ostream& svg, const FillCeilings& ceilings, bool any_threaded,
                    const LogScale& y_axis, const PlotLayout& layout) {
  const auto ceiling_line = [&](double mpix, const std::string& text, const char* dash) {
    const double y = y_axis.position(mpix);
    line(svg, layout.left, y, layout.right, y,
         {{"stroke", "#333"}, {"stroke-width", "1.5"}, {"stroke-dasharray", dash}});
    element(svg, "text",
            {{"x", layout.right - 4}, {"y", y - 5}, {"text-anchor", "end"}, {"fill", "#333"}},
            text);
  };
  open_group(svg);
  ceiling_line(ceilings.single_thread_mpix_per_s(),
               "write ceiling (memset, vector stores), 1 thread: " +
                   format_number(ceilings.single_thread_mpix_per_s(), 4) + " Mpix/s",
               "8 4");
  if (any_threaded && ceilings.threaded_mpix_per_s() > ceilings.single_thread_mpix_per_s()) {
    ceiling_line(ceilings.threaded_mpix_per_s(),
                 "write ceiling, " + std::to_string(ceilings.threads) +
                     " threads: " + format_number(ceilings.threaded_mpix_per_s(), 4) + " Mpix/s",
                 "3 3");
  }
  close_group(svg);
}

using PlotPoints = std::vector<std::pair<double, double>>;

// Each precision family joined by a line, drawn before the points so they sit on top.
void write_families(std::ostream& svg, std::span<const AlgorithmSummary> summaries,
                    const PlotPoints& at, const ChapterColours& colours) {
  open_group(svg, {{"fill", "none"}, {"stroke-width", "2"}, {"stroke-opacity", "0.7"}});
  for (const auto& family : precision_families(summaries)) {
    std::string points;
    for (std::size_t i = 0; i < family.size(); ++i) {
      points += (i == 0 ? "" : " ") + svg_number(at[family[i]].first) + ',' +
                svg_number(at[family[i]].second);
    }
    element(svg, "polyline",
            {{"stroke", colours.of(summaries[family.front()].chapter)}, {"points", points}});
  }
  close_group(svg);
}

// One circle per algorithm, with a tooltip; returns the labels still to be placed.
std::vector<Label> write_points(std::ostream& svg, std::span<const AlgorithmSummary> summaries,
                                const PlotPoints& at, const ChapterColours& colours) {
  std::vector<Label> labels;
  open_group(svg, {{"stroke", "black"}, {"stroke-width", "0.8"}});
  for (std::size_t i = 0; i < summaries.size(); ++i) {
    const AlgorithmSummary& s = summaries[i];
    const std::string title = escape_xml(s.algorithm) + " (" + escape_xml(s.chapter) + ", " +
                              escape_xml(s.rule) + "): " + format_number(s.mpix_per_s, 4) +
                              " Mpix/s, error " + format_number(s.error_rate(), 4);
    std::ostringstream tooltip;
    open_tag(tooltip, "title", {});
    tooltip << '>' << title << "</title>";
    element(
        svg, "circle",
        {{"cx", at[i].first}, {"cy", at[i].second}, {"r", "5"}, {"fill", colours.of(s.chapter)}},
        tooltip.str());
    Label label;
    label.point_x = at[i].first;
    label.point_y = at[i].second;
    label.text = s.algorithm + (s.threaded ? " (threads)" : "");
    labels.push_back(label);
  }
  close_group(svg);
  return labels;
}

// The placed labels, with a leader line when a label moved away from its point.
void write_labels(std::ostream& svg, const std::vector<Label>& labels) {
  open_group(svg, {{"fill", "#222"}});
  for (const Label& l : labels) {
    if (std::abs(l.y - (l.point_y + 4)) > 1) {
      line(svg, l.point_x, l.point_y, l.x, l.y - 4, {{"stroke", "#777"}, {"stroke-width", "0.8"}});
    }
    if (l.anchor_end) {
      element(svg, "text", {{"x", l.x}, {"y", l.y}, {"text-anchor", "end"}}, escape_xml(l.text));
    } else {
      element(svg, "text", {{"x", l.x}, {"y", l.y}}, escape_xml(l.text));
    }
  }
  close_group(svg);
}

// Chapters and their colours, then what the two kinds of line mean.
void write_legend(std::ostream& svg, const ChapterColours& colours, const PlotLayout& layout) {
  const double x = layout.right + 30;
  double y = layout.top + 10;
  open_group(svg);
  element(svg, "text", {{"x", x}, {"y", y}, {"font-weight", "bold"}}, "chapter");
  for (const std::string& chapter : colours.chapters) {
    y += 18;
    element(svg, "rect",
            {{"x", x},
             {"y", y - 9},
             {"width", "10"},
             {"height", "10"},
             {"stroke", "black"},
             {"stroke-width", "0.8"},
             {"fill", colours.of(chapter)}});
    element(svg, "text", {{"x", x + 16}, {"y", y}}, escape_xml(chapter));
  }
  y += 30;
  line(svg, x, y - 4, x + 24, y - 4, {{"stroke", "#888"}, {"stroke-width", "2"}});
  element(svg, "text", {{"x", x + 30}, {"y", y}}, "precision family,");
  element(svg, "text", {{"x", x + 30}, {"y", y + 13}}, "fewer to more bits");
  y += 32;
  line(svg, x, y - 4, x + 24, y - 4,
       {{"stroke", "#333"}, {"stroke-width", "1.5"}, {"stroke-dasharray", "8 4"}});
  element(svg, "text", {{"x", x + 30}, {"y", y}}, "write ceiling of the canvas");
  close_group(svg);
}

}  // namespace

ErrorAxis error_axis_for(std::span<const AlgorithmSummary> summaries, const PlotLayout& layout) {
  std::vector<double> rates;
  for (const AlgorithmSummary& s : summaries) rates.push_back(s.error_rate());
  const DecadeRange decades = decades_covering(rates);
  ErrorAxis axis;
  axis.scale = {decades.low, decades.high, layout.left + layout.floor_gap, layout.right};
  axis.zero_position = layout.left + layout.floor_gap / 2;
  return axis;
}

LogScale speed_scale_for(std::span<const AlgorithmSummary> summaries, const FillCeilings& ceilings,
                         bool any_threaded, const PlotLayout& layout) {
  std::vector<double> speeds{ceilings.single_thread_mpix_per_s()};
  if (any_threaded) speeds.push_back(ceilings.threaded_mpix_per_s());
  for (const AlgorithmSummary& s : summaries) speeds.push_back(s.mpix_per_s);
  const DecadeRange decades = decades_covering(speeds);
  return {decades.low, decades.high, layout.bottom, layout.top};
}

std::string to_svg(const BenchReport& report, std::span<const AlgorithmSummary> summaries,
                   const PlotLayout& layout) {
  const bool any_threaded = std::any_of(summaries.begin(), summaries.end(),
                                        [](const AlgorithmSummary& s) { return s.threaded; });
  const ErrorAxis x_axis = error_axis_for(summaries, layout);
  const LogScale y_axis = speed_scale_for(summaries, report.ceilings, any_threaded, layout);
  const ChapterColours colours(summaries);
  PlotPoints at;
  for (const AlgorithmSummary& s : summaries) {
    at.emplace_back(x_axis.position(s.error_rate()), y_axis.position(s.mpix_per_s));
  }
  std::ostringstream svg;
  write_header(svg, report, layout);
  write_grid(svg, x_axis, y_axis, layout);
  write_axes(svg, layout);
  write_x_labels(svg, x_axis, layout);
  write_y_labels(svg, y_axis, layout);
  write_ceilings(svg, report.ceilings, any_threaded, y_axis, layout);
  write_families(svg, summaries, at, colours);
  std::vector<Label> labels = write_points(svg, summaries, at, colours);
  place_labels(labels, layout);
  write_labels(svg, labels);
  write_legend(svg, colours, layout);
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace tri::ch10
