/// @file
/// The few SVG elements the report's plots are drawn with, written straight to a stream.
#pragma once

#include <initializer_list>
#include <ostream>
#include <string>
#include <string_view>

namespace tri {

/// A number as the plots write it: six significant digits.
std::string svg_number(double value);

/// One attribute of an SVG element; numbers are written as svg_number() writes them.
struct Attribute {
  Attribute(std::string_view name_, double value_) : name(name_), value(svg_number(value_)) {}
  Attribute(std::string_view name_, std::string value_) : name(name_), value(std::move(value_)) {}
  Attribute(std::string_view name_, const char* value_) : name(name_), value(value_) {}
  std::string_view name;
  std::string value;
};

/// `<name a="1" b="2"`, not yet closed.
void open_tag(std::ostream& svg, std::string_view name,
              std::initializer_list<Attribute> attributes);

/// An element without content: `<line x1="0" .../>`.
void element(std::ostream& svg, std::string_view name, std::initializer_list<Attribute> attributes);

/// An element with content, which is written as given (escape text first).
void element(std::ostream& svg, std::string_view name, std::initializer_list<Attribute> attributes,
             std::string_view content);

/// `<g ...>` and `</g>`.
void open_group(std::ostream& svg, std::initializer_list<Attribute> attributes = {});
void close_group(std::ostream& svg);

/// A line from (x1, y1) to (x2, y2) with its style attributes.
void line(std::ostream& svg, double x1, double y1, double x2, double y2,
          std::initializer_list<Attribute> style = {});

}  // namespace tri
