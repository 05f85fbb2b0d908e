#include "chapters/10_speed_vs_error/figure_parts.hpp"

#include <charconv>
#include <cmath>

#include "common/printable_text.hpp"
#include "measure/plot/svg_elements.hpp"

namespace tri::ch10::figure_parts {

std::string fixed(double value, int decimals) {
  char text[64];
  const auto [end, error] =
      std::to_chars(text, text + sizeof text, value, std::chars_format::fixed, decimals);
  return error == std::errc() ? std::string(text, end) : std::string("?");
}

std::string about_three_digits(double value) {
  const double size = std::abs(value);
  return fixed(value, size >= 100 ? 0 : size >= 10 ? 1 : 2);
}

void legend_swatch(std::ostream& svg, double x, double y, std::string_view fill,
                   std::string_view text, std::string_view stroke) {
  element(svg, "rect",
          {{"x", x},
           {"y", y},
           {"width", 12.0},
           {"height", 12.0},
           {"fill", std::string(fill)},
           {"stroke", std::string(stroke)},
           {"stroke-width", 2.0}});
  element(svg, "text", {{"x", x + 18}, {"y", y + 10}}, escape_xml(text));
}

void legend_dash(std::ostream& svg, double x, double y, std::string_view stroke,
                 std::string_view text) {
  line(svg, x - 2, y + 6, x + 14, y + 6,
       {{"stroke", std::string(stroke)}, {"stroke-width", 2.0}, {"stroke-dasharray", "5 3"}});
  element(svg, "text", {{"x", x + 18}, {"y", y + 10}}, escape_xml(text));
}

}  // namespace tri::ch10::figure_parts
