/// @file
/// What the chapter's deterministic figures share besides measure/plot: the Okabe-Ito colours of
/// the pixel diagrams (common/pixel_diagram.hpp) as SVG colours, fixed-decimal numbers, and the
/// legend's entries.
#pragma once

#include <ostream>
#include <string>
#include <string_view>

#include "common/pixel_diagram.hpp"

namespace tri::ch10::figure_parts {

// The diagrams' palette (common/pixel_diagram.hpp), as SVG text.
inline constexpr HexColor blue = hex_color(diagram_colors::blue);
inline constexpr HexColor sky_blue = hex_color(diagram_colors::sky_blue);
inline constexpr HexColor orange = hex_color(diagram_colors::orange);
inline constexpr HexColor vermillion = hex_color(diagram_colors::vermillion);
inline constexpr HexColor bluish_green = hex_color(diagram_colors::bluish_green);
inline constexpr HexColor grey = hex_color(diagram_colors::covered);

/// `value` with exactly `decimals` decimals ("1.00"), the same on every machine and locale.
std::string fixed(double value, int decimals);

/// `value` with about three significant digits and never an exponent: "4016", "857", "16.6",
/// "7.67", "0.52".
std::string about_three_digits(double value);

/// One legend entry: a 12x12 swatch filled with `fill` (outlined in `stroke` if given) at (x, y),
/// its top-left corner, and `text` to its right.
void legend_swatch(std::ostream& svg, double x, double y, std::string_view fill,
                   std::string_view text, std::string_view stroke = "none");

/// One legend entry: a dashed line segment in `stroke` at (x, y + 6) and `text` to its right.
void legend_dash(std::ostream& svg, double x, double y, std::string_view stroke,
                 std::string_view text);

}  // namespace tri::ch10::figure_parts
