/// @file
/// The truth for anti-aliasing: how much of each pixel a triangle covers, exactly. Pixel (i, j) is
/// the unit square centred on (i, j); its coverage is the area of its intersection with the
/// triangle, a fraction from 0 to 1, computed in exact fractions for vertices on the 1/256 grid.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

#include "chapters/09_anti_aliasing/fraction.hpp"
#include "common/triangle_algorithm.hpp"

namespace tri::ch09 {

/// The grid the oracle is exact on: 1/256 of a pixel, as in chapter 07's fixed point.
inline constexpr int oracle_subpixel_bits = 8;

/// Throws std::invalid_argument unless every vertex lies on the 1/256 grid within ±2^15 pixels,
/// where every fraction of the oracle fits in 128 bits for triangles up to about a canvas across.
void require_on_oracle_grid(const Triangle& triangle);

/// Step 1 · the truth: the area of the triangle inside pixel (i, j), the square
/// [i - 1/2, i + 1/2] x [j - 1/2, j + 1/2], as a fraction of the pixel. Either winding; zero for a
/// zero-area triangle. Exact: every intermediate is a fraction of 128-bit integers (an overflow
/// throws std::overflow_error).
Fraction exact_coverage(const Triangle& triangle, glm::ivec2 pixel);

/// The triangle's own area in pixels, exactly (the sum of its coverages over every pixel).
Fraction exact_area(const Triangle& triangle);

/// One pixel the triangle reaches into, with its exact coverage (greater than 0).
struct PixelCoverage {
  glm::ivec2 pixel;
  Fraction coverage;
};

/// Every pixel with coverage above zero, row by row from the lowest y, each row left to right.
std::vector<PixelCoverage> exact_coverages(const Triangle& triangle);

/// One edge a -> b inside pixel's row of pixels (the band pixel.y - 1/2 <= y <= pixel.y + 1/2),
/// split at the pixel's left and right sides. Heights are signed: positive where the edge rises.
/// Exact, in pixels. Step 1 and step 4 add up the same pieces measured from opposite sides.
struct EdgeInPixelRow {
  Fraction left_height;    ///< the part left of the pixel
  Fraction inside_height;  ///< the part across the pixel
  Fraction right_height;   ///< the part right of the pixel
  Fraction inside_mean_x;  ///< the inside part's mean x, from the pixel's left side (0 to 1)

  /// Step 1's share, h measured from the pixel's left side: the trapezoid between the inside part
  /// and the left side, plus the whole width for the part right of the pixel.
  Fraction from_left() const { return inside_height * inside_mean_x + right_height; }
  /// Step 4's area in the cell: the trapezoid between the inside part and the right side.
  Fraction area() const { return inside_height * (Fraction(1) - inside_mean_x); }
  /// Step 4's cover: the part left of the cell counts for the cell's whole width.
  Fraction cover() const { return left_height; }
};

/// Step 1's part of one edge a -> b for pixel (i, j): the listing's edge_area, the integral of
/// h = clamp(x, left side, right side) - left side along the edge's part in the pixel's rows.
Fraction edge_area_in_pixel(glm::dvec2 a, glm::dvec2 b, glm::ivec2 pixel);

/// Step 1's edge split for one pixel (vertices on the 1/256 grid, as exact_coverage requires).
/// For a counter-clockwise triangle (y up) the three edges' from_left() add up to +coverage and
/// their area() + cover() to -coverage: the two steps measure from opposite sides.
EdgeInPixelRow edge_in_pixel_row(glm::dvec2 a, glm::dvec2 b, glm::ivec2 pixel);

/// A coverage as the 16-bit value the PGM output stores: round(65535 x c) with halves rounded
/// up, c clamped to [0, 1] first.
std::uint16_t coverage_16(const Fraction& coverage);

}  // namespace tri::ch09
