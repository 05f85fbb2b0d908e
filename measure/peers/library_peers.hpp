/// @file
/// The peers from the 2-D libraries people call, each built only where its library was found:
/// pixman's own triangle rasterizer (pixman_add_triangles, the one under cairo and the X server),
/// cairo filling one triangle path at a time, and AGG's exact-area scanline rasterizer. Without
/// anti-aliasing (pixman, cairo) they are external peers of the report's first part; with it
/// (all three) they are coverage peers of its second part.
#pragma once

#include <span>
#include <string>

#include "measure/error_metrics.hpp"
#include "measure/peers/peer.hpp"

namespace tri {

/// pixman's 16.16 fixed point holds coordinates up to 32767 in magnitude.
inline constexpr double pixman_coordinate_limit = 32767.0;
/// cairo keeps coordinates in 24.8 fixed point: about 8 million pixels in magnitude.
inline constexpr double cairo_coordinate_limit = 8.0e6;
/// AGG's limit: its rasterizer keeps coordinates in 24.8 fixed point in an int.
inline constexpr double agg_coordinate_limit = 1 << 22;
/// FreeType's spans give a pixel's x as a short: 32767 in magnitude.
inline constexpr double freetype_coordinate_limit = 32767.0;

/// The pixels pixman sets for each triangle, counted: every triangle is added on its own into a
/// cleared one-bit (a1) image, so a pixel two triangles cover counts 2. Throws for scenes beyond
/// pixman_coordinate_limit.
WriteCounts pixman_write_counts(int width, int height, std::span<const SceneTriangle> triangles);

/// The pixels cairo fills for each triangle (CAIRO_ANTIALIAS_NONE), counted: every triangle is
/// filled on its own into a cleared 8-bit alpha surface. Throws for scenes beyond
/// cairo_coordinate_limit.
WriteCounts cairo_write_counts(int width, int height, std::span<const SceneTriangle> triangles);

/// "pixman_a1": pixman_add_triangles into a one-bit image of the canvas size, the whole frame in
/// one call, as a user would draw it, with its error against the oracle.
ExternalPeer pixman_peer();

/// "cairo_no_antialias": cairo_fill of one triangle path per triangle on an ARGB32 surface of the
/// canvas size, with CAIRO_ANTIALIAS_NONE, timed like the book's algorithms.
ExternalPeer cairo_peer();

/// "pixman 0.42.2": the pixman this process runs with.
std::string pixman_version();

/// "cairo 1.16.0": the cairo this process runs with.
std::string cairo_version();

/// "agg_scanline_aa": agg::rasterizer_scanline_aa (no gamma) into a gray8 image, one path per
/// triangle, rendered with render_scanlines_aa_solid.
CoveragePeer agg_coverage_peer();

/// "cairo_antialias": cairo_fill of one triangle path per call on an A8 surface, with cairo's
/// default anti-aliasing and the ADD operator, so coverages add up as a summed canvas does.
CoveragePeer cairo_coverage_peer();

/// "freetype_smooth": FreeType's smooth rasterizer (FT_Outline_Render, anti-aliased, spans added
/// into a gray image), one three-point outline per triangle, its coordinates in 26.6 fixed point.
CoveragePeer freetype_coverage_peer();

/// "FreeType 2.12.1": the FreeType this process runs with.
std::string freetype_version();

/// "pixman_a8": pixman_add_triangles into an a8 image, one call per triangle (it adds,
/// saturating at 255).
CoveragePeer pixman_coverage_peer();

}  // namespace tri
