/// @file
/// The anti-aliasing peers, each built only where its library was found: AGG's exact-area
/// scanline rasterizer, cairo's default anti-aliasing, pixman's a8 triangles.
#pragma once

#include "chapters/09_speed_vs_error/coverage_measure.hpp"

namespace tri::ch09 {

/// AGG's limit: its rasterizer keeps coordinates in 24.8 fixed point in an int.
inline constexpr double agg_coordinate_limit = 1 << 22;

/// "agg_scanline_aa": agg::rasterizer_scanline_aa (no gamma) into a gray8 image, one path per
/// triangle, rendered with render_scanlines_aa_solid.
CoveragePeer agg_coverage_peer();

/// "cairo_antialias": cairo_fill of one triangle path per call on an A8 surface, with cairo's
/// default anti-aliasing and the ADD operator, so coverages add up as a summed canvas does.
CoveragePeer cairo_coverage_peer();

/// "pixman_a8": pixman_add_triangles into an a8 image, one call per triangle (it adds,
/// saturating at 255).
CoveragePeer pixman_coverage_peer();

}  // namespace tri::ch09
