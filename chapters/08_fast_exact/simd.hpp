/// @file
/// Step 5 · SIMD: step 4's partial blocks tested eight pixels of a row at a time, in 32-bit lanes
/// whenever the triangle's edge values provably fit, and written with one blend of eight pixels.
#pragma once

#include <array>
#include <cstdint>

#include "chapters/08_fast_exact/pixel_writers.hpp"
#include "chapters/08_fast_exact/triangle_setup.hpp"
#include "common/canvas.hpp"
#include "common/color.hpp"
#include "common/triangle_algorithm.hpp"

namespace tri::ch08 {

/// The longest vertex extent (1/256 pixel units) for which 32-bit lanes are safe: 2^18, i.e.
/// 1024 pixels.
inline constexpr std::int64_t max_extent_for_32_bit_lanes = std::int64_t{1} << 18;

/// True when every edge value the SIMD variant forms for this setup fits in 32 bits, so eight
/// lanes fill one 256-bit vector instead of two. The lanes reach at most 7 pixels right of and one
/// row above the candidate pixels, so every point p they evaluate lies within D + 2048 of a
/// vertex on each axis (D = vertex_extent), and |E| <= 2 D (D + 2048). For D <= 2^18 that is below
/// 2^38, and E / 256 (plus the bias) stays below 2^30 + 2: well inside 32 bits.
constexpr bool fits_32_bit_lanes(const TriangleSetup& setup) noexcept {
  return setup.vertex_extent <= max_extent_for_32_bit_lanes;
}

/// True when the setup's candidate pixels fit in one 8x8 block: step 5 then tests its rows at
/// once without classifying it, in 4 lanes when it is at most 4 pixels wide.
constexpr bool fits_one_block(const TriangleSetup& setup) noexcept {
  const ch05::PixelBox& r = setup.range;
  return r.max.x - r.min.x < 8 && r.max.y - r.min.y < 8;
}

/// The lane width of the lane test.
enum class LaneWidth { bits32, bits64 };

/// What the lane test says about pixels (x + i, y), 0 <= i < lanes (4 or 8), of the setup's
/// range: lane i is the OR of the three edge values there and of (range.max.x - x - i), and the
/// pixel is drawn when it is >= 0, i.e. when it is covered and inside the range. The same vector
/// code the variant runs, exposed for tests (bits32 only where fits_32_bit_lanes holds); entries
/// from `lanes` on are false.
std::array<bool, 8> lane_test(const TriangleSetup& setup, int x, int y, LaneWidth width, int lanes);

/// Step 5 · SIMD: step 4's blocks, each row of a partial block tested by the lane test and
/// written with one read-blend-write of eight pixels; a triangle within one block skips the
/// blocks altogether; what step 6 runs on the triangles within one block. Compiled with its
/// canvas entries in simd.cpp: draw_triangle_simd, and OnCanvas' draw_rows.
void fill_simd(const TriangleSetup& setup, CanvasWriter writer);
extern template struct OnCanvas<fill_simd>;
inline constexpr DrawTriangleFunction draw_triangle_simd = OnCanvas<fill_simd>::draw;

}  // namespace tri::ch08
