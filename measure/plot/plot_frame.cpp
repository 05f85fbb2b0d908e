#include "measure/plot/plot_frame.hpp"

#include <cmath>

#include "common/printable_text.hpp"
#include "measure/plot/svg_elements.hpp"

namespace tri {

void open_plot(std::ostream& svg, double width, double height, double left, std::string_view title,
               std::string_view subtitle, std::string_view note) {
  open_tag(svg, "svg",
           {{"xmlns", "http://www.w3.org/2000/svg"},
            {"width", width},
            {"height", height},
            {"viewBox", "0 0 " + svg_number(width) + ' ' + svg_number(height)},
            {"font-family", "sans-serif"},
            {"font-size", "11"}});
  svg << ">\n";
  element(svg, "rect",
          {{"x", "0"}, {"y", "0"}, {"width", width}, {"height", height}, {"fill", "white"}});
  element(svg, "text", {{"x", left}, {"y", "28"}, {"font-size", "16"}, {"font-weight", "bold"}},
          escape_xml(title));
  element(svg, "text", {{"x", left}, {"y", "48"}}, escape_xml(subtitle));
  element(svg, "text", {{"x", left}, {"y", "64"}, {"fill", "#555"}}, escape_xml(note));
}

void log_grid_and_axes(std::ostream& svg, const LogScale& x, const LogScale& y,
                       const PlotBox& box) {
  open_group(svg, {{"stroke", "#ddd"}});
  for (int k = x.low_decade; k <= x.high_decade; ++k) {
    const double at = x.position(std::pow(10.0, k));
    line(svg, at, box.top, at, box.bottom);
  }
  for (int k = y.low_decade; k <= y.high_decade; ++k) {
    const double at = y.position(std::pow(10.0, k));
    line(svg, box.left, at, box.right, at);
  }
  close_group(svg);
  line(svg, box.left, box.bottom, box.right, box.bottom, {{"stroke", "black"}});
  line(svg, box.left, box.top, box.left, box.bottom, {{"stroke", "black"}});
}

void x_decade_labels(std::ostream& svg, const LogScale& x, const PlotBox& box,
                     std::string_view title) {
  open_group(svg, {{"text-anchor", "middle"}});
  for (int k = x.low_decade; k <= x.high_decade; ++k) {
    element(svg, "text", {{"x", x.position(std::pow(10.0, k))}, {"y", box.bottom + 16}},
            power_of_ten_label(k));
  }
  element(svg, "text",
          {{"x", (box.left + box.right) / 2}, {"y", box.bottom + 38}, {"font-size", "13"}},
          escape_xml(title));
  close_group(svg);
}

void y_decade_labels(std::ostream& svg, const LogScale& y, const PlotBox& box,
                     std::string (*label)(int), std::string_view title) {
  open_group(svg, {{"text-anchor", "end"}});
  for (int k = y.low_decade; k <= y.high_decade; ++k) {
    element(svg, "text", {{"x", box.left - 6}, {"y", y.position(std::pow(10.0, k)) + 4}}, label(k));
  }
  close_group(svg);
  y_axis_title(svg, box, 58, title);
}

void y_axis_title(std::ostream& svg, const PlotBox& box, double distance, std::string_view title) {
  element(svg, "text",
          {{"transform", "translate(" + svg_number(box.left - distance) + ' ' +
                             svg_number((box.top + box.bottom) / 2) + ") rotate(-90)"},
           {"text-anchor", "middle"},
           {"font-size", "13"}},
          escape_xml(title));
}

}  // namespace tri
