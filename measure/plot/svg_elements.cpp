#include "measure/plot/svg_elements.hpp"

#include "measure/number_format.hpp"

namespace tri {

std::string svg_number(double value) {
  return format_number(value, 6);
}

void open_tag(std::ostream& svg, std::string_view name,
              std::initializer_list<Attribute> attributes) {
  svg << '<' << name;
  for (const Attribute& a : attributes) svg << ' ' << a.name << "=\"" << a.value << '"';
}

void element(std::ostream& svg, std::string_view name,
             std::initializer_list<Attribute> attributes) {
  open_tag(svg, name, attributes);
  svg << "/>\n";
}

void element(std::ostream& svg, std::string_view name, std::initializer_list<Attribute> attributes,
             std::string_view content) {
  open_tag(svg, name, attributes);
  svg << '>' << content << "</" << name << ">\n";
}

void open_group(std::ostream& svg, std::initializer_list<Attribute> attributes) {
  open_tag(svg, "g", attributes);
  svg << ">\n";
}

void close_group(std::ostream& svg) {
  svg << "</g>\n";
}

void line(std::ostream& svg, double x1, double y1, double x2, double y2,
          std::initializer_list<Attribute> style) {
  open_tag(svg, "line", {{"x1", x1}, {"y1", y1}, {"x2", x2}, {"y2", y2}});
  for (const Attribute& a : style) svg << ' ' << a.name << "=\"" << a.value << '"';
  svg << "/>\n";
}

}  // namespace tri
