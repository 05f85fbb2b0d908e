/// @file
/// pixman's own triangle rasterizer (pixman_add_triangles, the one under cairo and the X server)
/// as an external peer of the report. Built only where pixman's headers were found.
#pragma once

#include <span>

#include "chapters/09_speed_vs_error/measure.hpp"
#include "measure/error_metrics.hpp"

namespace tri::ch09 {

/// pixman's 16.16 fixed point holds coordinates up to 32767 in magnitude.
inline constexpr double pixman_coordinate_limit = 32767.0;

/// The pixels pixman sets for each triangle, counted: every triangle is added on its own into a
/// cleared one-bit (a1) image, so a pixel two triangles cover counts 2. Throws for scenes beyond
/// pixman_coordinate_limit.
WriteCounts pixman_write_counts(int width, int height, std::span<const SceneTriangle> triangles);

/// "pixman_a1": pixman_add_triangles into a one-bit image of the canvas size, one call per
/// triangle, timed like the book's algorithms, with its error against the oracle.
ExternalPeer pixman_peer();

}  // namespace tri::ch09
