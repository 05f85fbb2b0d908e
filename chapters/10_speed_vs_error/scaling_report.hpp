/// @file
/// The report's third part, how cost grows: 10_scaling.csv, the Markdown section with its two
/// tables, and one log-log plot per sweep (10_scaling_triangles.svg, 10_scaling_canvas.svg).
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "chapters/10_speed_vs_error/scaling.hpp"

namespace tri::ch10 {

/// The header and one line per point of either sweep.
std::string scaling_csv(std::span<const ScalingPoint> points);

/// How a drawer's time grows between its first and its last measured point of one sweep and
/// scene: the exponent k of time ∝ x^k, x the triangles or the canvas's pixels; 0 with fewer than
/// two measured points.
double growth_exponent(std::span<const ScalingPoint> points, std::string_view sweep,
                       std::string_view scene, std::string_view drawer);

/// The Markdown section "How cost grows" (empty without points).
std::string scaling_markdown(std::span<const ScalingPoint> points);

/// The plot of one sweep ("triangles" or "canvas"): x the triangles or the canvas's pixels, y the
/// milliseconds per frame, both log; one line per drawer and scene, a dashed guide of slope 1.
std::string scaling_svg(std::span<const ScalingPoint> points, std::string_view sweep,
                        const std::string& subtitle);

}  // namespace tri::ch10
