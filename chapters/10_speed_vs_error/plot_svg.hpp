/// @file
/// 10_speed_vs_error.svg, drawn by hand: error per covered pixel across (log, with "exact" at a
/// floor), written Mpixels/s up (log), one labelled point per algorithm coloured by chapter,
/// precision families joined by lines, the write ceiling as a horizontal line.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "measure/plot/log_axis.hpp"
#include "chapters/10_speed_vs_error/measure.hpp"
#include "chapters/10_speed_vs_error/summary.hpp"
#include "common/printable_text.hpp"

namespace tri::ch10 {

/// Where the plot area sits in the SVG (pixels, y down).
struct PlotLayout {
  double width = 980;
  double height = 640;
  double left = 90;    ///< the "exact" floor sits just right of this
  double right = 720;  ///< the legend is to the right of this
  double top = 80;
  double bottom = 560;
  double floor_gap = 70;  ///< room between the "exact" floor and the first decade
};

/// The x axis for these error rates: the decades holding every positive rate, and 0 at a floor
/// floor_gap / 2 left of the first decade.
ErrorAxis error_axis_for(std::span<const AlgorithmSummary> summaries, const PlotLayout& layout);

/// The y axis: the decades holding every algorithm's Mpix/s and the ceilings, growing upward.
LogScale speed_scale_for(std::span<const AlgorithmSummary> summaries, const FillCeilings& ceilings,
                         bool any_threaded, const PlotLayout& layout);

/// The whole SVG document (it starts with `<svg`); one `<circle>` per summary, nothing else uses
/// circles.
std::string to_svg(const BenchReport& report, std::span<const AlgorithmSummary> summaries,
                   const PlotLayout& layout = {});

}  // namespace tri::ch10
