/// @file
/// What the chapter's deterministic figures share besides measure/plot: the Okabe-Ito colours of
/// the pixel diagrams (common/pixel_diagram.hpp) as SVG colours, fixed-decimal numbers, and the
/// legend's entries.
#pragma once

#include <ostream>
#include <string>
#include <string_view>

namespace tri::ch10::figure_parts {

inline constexpr const char* blue = "#0072b2";
inline constexpr const char* sky_blue = "#56b4e9";
inline constexpr const char* orange = "#e69f00";
inline constexpr const char* vermillion = "#d55e00";
inline constexpr const char* bluish_green = "#009e73";
inline constexpr const char* grey = "#a0a0a0";

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
