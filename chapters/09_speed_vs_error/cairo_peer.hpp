/// @file
/// cairo, the 2-D library most programs call, filling one triangle path at a time without
/// anti-aliasing, as an external peer of the report. Built only where cairo's headers were found.
#pragma once

#include <span>

#include "chapters/09_speed_vs_error/measure.hpp"
#include "measure/error_metrics.hpp"

namespace tri::ch09 {

/// cairo keeps coordinates in 24.8 fixed point: about 8 million pixels in magnitude.
inline constexpr double cairo_coordinate_limit = 8.0e6;

/// The pixels cairo fills for each triangle (CAIRO_ANTIALIAS_NONE), counted: every triangle is
/// filled on its own into a cleared 8-bit alpha surface. Throws for scenes beyond
/// cairo_coordinate_limit.
WriteCounts cairo_write_counts(int width, int height, std::span<const SceneTriangle> triangles);

/// "cairo_no_antialias": cairo_fill of one triangle path per triangle on an ARGB32 surface of the
/// canvas size, with CAIRO_ANTIALIAS_NONE, timed like the book's algorithms.
ExternalPeer cairo_peer();

}  // namespace tri::ch09
