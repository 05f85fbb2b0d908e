/// @file
/// What the report's log-log plots share: the page with its three lines of title, and the frame of
/// a plot area whose axes are whole decades (grid, axes, decade labels, axis titles).
#pragma once

#include <ostream>
#include <string>
#include <string_view>

#include "measure/plot/log_axis.hpp"

namespace tri {

/// Where a plot area sits in its SVG (pixels, y down).
struct PlotBox {
  double left = 0, right = 0, top = 0, bottom = 0;
};

/// Opens the `<svg>` document (width x height, sans-serif 11) on a white page with a bold title,
/// the subtitle under it and a grey note under that, each starting at x = left and escaped here.
/// The caller ends the document with `</svg>`.
void open_plot(std::ostream& svg, double width, double height, double left, std::string_view title,
               std::string_view subtitle, std::string_view note);

/// Light lines at every decade of both scales across the box, then the two axes in black.
void log_grid_and_axes(std::ostream& svg, const LogScale& x, const LogScale& y, const PlotBox& box);

/// The decades of x labelled under the box ("10ⁿ"), and the axis's title centred below them.
void x_decade_labels(std::ostream& svg, const LogScale& x, const PlotBox& box,
                     std::string_view title);

/// An upright axis title centred beside the box's left side, `distance` pixels left of it.
void y_axis_title(std::ostream& svg, const PlotBox& box, double distance, std::string_view title);

/// The decades of y labelled left of the box by `label`, and the axis's title turned upright.
void y_decade_labels(std::ostream& svg, const LogScale& y, const PlotBox& box,
                     std::string (*label)(int), std::string_view title);

}  // namespace tri
