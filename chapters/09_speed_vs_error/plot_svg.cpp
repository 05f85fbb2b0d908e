#include "chapters/09_speed_vs_error/plot_svg.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <sstream>
#include <vector>

#include "chapters/09_speed_vs_error/report_csv.hpp"

namespace tri::ch09 {
namespace {

// Ten colours that stay apart for colour-blind readers (Tableau 10), one per chapter.
constexpr std::array<const char*, 10> palette{"#4e79a7", "#f28e2b", "#e15759", "#76b7b2",
                                              "#59a14f", "#edc948", "#b07aa1", "#ff9da7",
                                              "#9c755f", "#bab0ac"};

constexpr double label_height = 12;       // px between label baselines
constexpr double label_char_width = 6.4;  // px per character at font-size 11

std::string number(double value) {
  return format_number(value, 6);
}

std::string superscript(int exponent) {
  static constexpr std::array<const char*, 10> digits{"⁰", "¹", "²", "³", "⁴",
                                                      "⁵", "⁶", "⁷", "⁸", "⁹"};
  std::string text = exponent < 0 ? "⁻" : "";
  for (const char c : std::to_string(std::abs(exponent))) text += digits[c - '0'];
  return text;
}

// 10^k as a plain number for moderate k, as 10ⁿ beyond.
std::string decade_label(int k) {
  if (k >= -3 && k <= 5) return format_number(std::pow(10.0, k), 6);
  return "10" + superscript(k);
}

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
  std::vector<double> speeds{ceilings.single_thread_mpix_per_s};
  if (any_threaded) speeds.push_back(ceilings.threaded_mpix_per_s());
  for (const AlgorithmSummary& s : summaries) speeds.push_back(s.mpix_per_s);
  const DecadeRange decades = decades_covering(speeds);
  return {decades.low, decades.high, layout.bottom, layout.top};
}

std::string escape_xml(std::string_view text) {
  std::string escaped;
  for (const char c : text) {
    switch (c) {
      case '&':
        escaped += "&amp;";
        break;
      case '<':
        escaped += "&lt;";
        break;
      case '>':
        escaped += "&gt;";
        break;
      case '"':
        escaped += "&quot;";
        break;
      default:
        escaped += c;
    }
  }
  return escaped;
}

std::string to_svg(const BenchReport& report, std::span<const AlgorithmSummary> summaries,
                   const PlotLayout& layout) {
  const bool any_threaded = std::any_of(summaries.begin(), summaries.end(),
                                        [](const AlgorithmSummary& s) { return s.threaded; });
  const ErrorAxis x_axis = error_axis_for(summaries, layout);
  const LogScale y_axis = speed_scale_for(summaries, report.ceilings, any_threaded, layout);
  std::map<std::string, std::size_t> chapter_colour;
  std::vector<std::string> chapters;
  for (const AlgorithmSummary& s : summaries) {
    if (chapter_colour.try_emplace(s.chapter, chapters.size()).second)
      chapters.push_back(s.chapter);
  }
  const auto colour_of = [&](const std::string& chapter) {
    return palette[chapter_colour.at(chapter) % palette.size()];
  };

  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << number(layout.width)
      << "\" height=\"" << number(layout.height) << "\" viewBox=\"0 0 " << number(layout.width)
      << ' ' << number(layout.height) << "\" font-family=\"sans-serif\" font-size=\"11\">\n"
      << "<rect x=\"0\" y=\"0\" width=\"" << number(layout.width) << "\" height=\""
      << number(layout.height) << "\" fill=\"white\"/>\n";
  svg << "<text x=\"" << number(layout.left) << "\" y=\"28\" font-size=\"16\" "
      << "font-weight=\"bold\">Speed against error, every registered algorithm</text>\n"
      << "<text x=\"" << number(layout.left) << "\" y=\"48\">" << size_name(report.size)
      << " setting, " << report.width << "×" << report.height << " canvas, "
      << escape_xml(report.machine.cpu_model) << " (" << report.machine.threads << " threads), "
      << escape_xml(report.machine.compiler) << ", " << escape_xml(report.machine.build_type)
      << "</text>\n"
      << "<text x=\"" << number(layout.left)
      << "\" y=\"64\" fill=\"#555\">y: pixels written per second (Mpix/s), geometric mean over "
         "all scenes; x: (missed + extra) per covered pixel over all scenes</text>\n";

  // Grid and axes.
  svg << "<g stroke=\"#ddd\" stroke-width=\"1\">\n";
  for (int k = x_axis.scale.low_decade; k <= x_axis.scale.high_decade; ++k) {
    const double x = x_axis.scale.position(std::pow(10.0, k));
    svg << "<line x1=\"" << number(x) << "\" y1=\"" << number(layout.top) << "\" x2=\"" << number(x)
        << "\" y2=\"" << number(layout.bottom) << "\"/>\n";
  }
  for (int k = y_axis.low_decade; k <= y_axis.high_decade; ++k) {
    const double y = y_axis.position(std::pow(10.0, k));
    svg << "<line x1=\"" << number(layout.left) << "\" y1=\"" << number(y) << "\" x2=\""
        << number(layout.right) << "\" y2=\"" << number(y) << "\"/>\n";
  }
  svg << "<line x1=\"" << number(x_axis.zero_position) << "\" y1=\"" << number(layout.top)
      << "\" x2=\"" << number(x_axis.zero_position) << "\" y2=\"" << number(layout.bottom)
      << "\" stroke-dasharray=\"2 3\"/>\n</g>\n";
  svg << "<g stroke=\"black\" stroke-width=\"1\" fill=\"none\">\n"
      << "<line x1=\"" << number(layout.left) << "\" y1=\"" << number(layout.bottom) << "\" x2=\""
      << number(layout.right) << "\" y2=\"" << number(layout.bottom) << "\"/>\n"
      << "<line x1=\"" << number(layout.left) << "\" y1=\"" << number(layout.top) << "\" x2=\""
      << number(layout.left) << "\" y2=\"" << number(layout.bottom) << "\"/>\n";
  // The axis break between "exact" and the first decade: log 0 is not on the scale.
  const double break_x = layout.left + 0.75 * layout.floor_gap;
  for (const double dx : {-3.0, 3.0}) {
    svg << "<line x1=\"" << number(break_x + dx - 3) << "\" y1=\"" << number(layout.bottom + 5)
        << "\" x2=\"" << number(break_x + dx + 3) << "\" y2=\"" << number(layout.bottom - 5)
        << "\"/>\n";
  }
  svg << "</g>\n";
  svg << "<g text-anchor=\"middle\">\n";
  svg << "<text x=\"" << number(x_axis.zero_position) << "\" y=\"" << number(layout.bottom + 16)
      << "\" font-weight=\"bold\">exact</text>\n";
  for (int k = x_axis.scale.low_decade; k <= x_axis.scale.high_decade; ++k) {
    svg << "<text x=\"" << number(x_axis.scale.position(std::pow(10.0, k))) << "\" y=\""
        << number(layout.bottom + 16) << "\">10" << superscript(k) << "</text>\n";
  }
  svg << "<text x=\"" << number((layout.left + layout.right) / 2) << "\" y=\""
      << number(layout.bottom + 38)
      << "\" font-size=\"13\">error: wrong pixels per covered pixel (log; 0 drawn at "
         "\"exact\")</text>\n</g>\n";
  svg << "<g text-anchor=\"end\">\n";
  for (int k = y_axis.low_decade; k <= y_axis.high_decade; ++k) {
    svg << "<text x=\"" << number(layout.left - 6) << "\" y=\""
        << number(y_axis.position(std::pow(10.0, k)) + 4) << "\">" << decade_label(k)
        << "</text>\n";
  }
  const double middle_y = (layout.top + layout.bottom) / 2;
  svg << "<text x=\"0\" y=\"0\" font-size=\"13\" text-anchor=\"middle\" transform=\"translate("
      << number(layout.left - 58) << ' ' << number(middle_y)
      << ") rotate(-90)\">speed: Mpixels written per second (log)</text>\n</g>\n";

  // The std::fill ceilings.
  const auto ceiling_line = [&](double mpix, const std::string& text, const char* dash) {
    const double y = y_axis.position(mpix);
    svg << "<line x1=\"" << number(layout.left) << "\" y1=\"" << number(y) << "\" x2=\""
        << number(layout.right) << "\" y2=\"" << number(y)
        << "\" stroke=\"#333\" stroke-width=\"1.5\" stroke-dasharray=\"" << dash << "\"/>\n"
        << "<text x=\"" << number(layout.right - 4) << "\" y=\"" << number(y - 5)
        << "\" text-anchor=\"end\" fill=\"#333\">" << text << "</text>\n";
  };
  svg << "<g>\n";
  ceiling_line(report.ceilings.single_thread_mpix_per_s,
               "std::fill ceiling, 1 thread: " +
                   format_number(report.ceilings.single_thread_mpix_per_s, 4) + " Mpix/s",
               "8 4");
  if (any_threaded &&
      report.ceilings.threaded_mpix_per_s() > report.ceilings.single_thread_mpix_per_s) {
    ceiling_line(report.ceilings.threaded_mpix_per_s(),
                 "std::fill ceiling, " + std::to_string(report.ceilings.threads) + " threads: " +
                     format_number(report.ceilings.threaded_mpix_per_s(), 4) + " Mpix/s",
                 "3 3");
  }
  svg << "</g>\n";

  // Points, families first so the points sit on top of their lines.
  std::vector<Label> labels;
  std::vector<std::pair<double, double>> at;
  for (const AlgorithmSummary& s : summaries) {
    at.emplace_back(x_axis.position(s.error_rate()), y_axis.position(s.mpix_per_s));
  }
  svg << "<g fill=\"none\" stroke-width=\"2\" stroke-opacity=\"0.7\">\n";
  for (const auto& family : precision_families(summaries)) {
    svg << "<polyline stroke=\"" << colour_of(summaries[family.front()].chapter) << "\" points=\"";
    for (std::size_t i = 0; i < family.size(); ++i) {
      svg << (i == 0 ? "" : " ") << number(at[family[i]].first) << ','
          << number(at[family[i]].second);
    }
    svg << "\"/>\n";
  }
  svg << "</g>\n<g stroke=\"black\" stroke-width=\"0.8\">\n";
  for (std::size_t i = 0; i < summaries.size(); ++i) {
    const AlgorithmSummary& s = summaries[i];
    svg << "<circle cx=\"" << number(at[i].first) << "\" cy=\"" << number(at[i].second)
        << "\" r=\"5\" fill=\"" << colour_of(s.chapter) << "\"><title>" << escape_xml(s.algorithm)
        << " (" << escape_xml(s.chapter) << ", " << escape_xml(s.rule)
        << "): " << format_number(s.mpix_per_s, 4) << " Mpix/s, error "
        << format_number(s.error_rate(), 4) << "</title></circle>\n";
    Label label;
    label.point_x = at[i].first;
    label.point_y = at[i].second;
    label.text = s.algorithm + (s.threaded ? " (threads)" : "");
    labels.push_back(label);
  }
  svg << "</g>\n";
  place_labels(labels, layout);
  svg << "<g fill=\"#222\">\n";
  for (const Label& l : labels) {
    if (std::abs(l.y - (l.point_y + 4)) > 1) {
      svg << "<line x1=\"" << number(l.point_x) << "\" y1=\"" << number(l.point_y) << "\" x2=\""
          << number(l.x) << "\" y2=\"" << number(l.y - 4) << "\" stroke=\"#777\" "
          << "stroke-width=\"0.8\"/>\n";
    }
    svg << "<text x=\"" << number(l.x) << "\" y=\"" << number(l.y) << "\""
        << (l.anchor_end ? " text-anchor=\"end\"" : "") << ">" << escape_xml(l.text) << "</text>\n";
  }
  svg << "</g>\n";

  // Legend: chapters, then what the lines mean.
  const double legend_x = layout.right + 30;
  double legend_y = layout.top + 10;
  svg << "<g>\n<text x=\"" << number(legend_x) << "\" y=\"" << number(legend_y)
      << "\" font-weight=\"bold\">chapter</text>\n";
  for (const std::string& chapter : chapters) {
    legend_y += 18;
    svg << "<rect x=\"" << number(legend_x) << "\" y=\"" << number(legend_y - 9)
        << "\" width=\"10\" height=\"10\" stroke=\"black\" stroke-width=\"0.8\" fill=\""
        << colour_of(chapter) << "\"/>\n<text x=\"" << number(legend_x + 16) << "\" y=\""
        << number(legend_y) << "\">" << escape_xml(chapter) << "</text>\n";
  }
  legend_y += 30;
  svg << "<line x1=\"" << number(legend_x) << "\" y1=\"" << number(legend_y - 4) << "\" x2=\""
      << number(legend_x + 24) << "\" y2=\"" << number(legend_y - 4)
      << "\" stroke=\"#888\" stroke-width=\"2\"/>\n<text x=\"" << number(legend_x + 30) << "\" y=\""
      << number(legend_y) << "\">precision family,</text>\n<text x=\"" << number(legend_x + 30)
      << "\" y=\"" << number(legend_y + 13) << "\">fewer to more bits</text>\n";
  legend_y += 32;
  svg << "<line x1=\"" << number(legend_x) << "\" y1=\"" << number(legend_y - 4) << "\" x2=\""
      << number(legend_x + 24) << "\" y2=\"" << number(legend_y - 4)
      << "\" stroke=\"#333\" stroke-width=\"1.5\" stroke-dasharray=\"8 4\"/>\n<text x=\""
      << number(legend_x + 30) << "\" y=\"" << number(legend_y)
      << "\">std::fill of the canvas</text>\n</g>\n";
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace tri::ch09
