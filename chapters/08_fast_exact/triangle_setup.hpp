/// @file
/// What every fast variant starts from: chapter 07's snapped vertices turned, once per triangle,
/// into three edge functions of integer pixel coordinates whose sign alone decides coverage.
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "chapters/07_exact_coverage/fixed_point.hpp"
#include "common/canvas.hpp"
#include "common/triangle_algorithm.hpp"

namespace tri::ch08 {

/// Every variant works on chapter 07's 1/256 grid (8 fractional bits).
inline constexpr int subpixel_bits = 8;

/// floor(x) as an integer, exactly, for |x| < 2^62: truncate, then step down when truncation
/// went up (negative non-integers). std::floor is a library call on baseline x86-64.
inline std::int64_t floor_to_integer(double x) noexcept {
  const auto truncated = static_cast<std::int64_t>(x);
  return static_cast<double>(truncated) > x ? truncated - 1 : truncated;
}

/// The nearest integer to x, halves up, for |x| < 2^52 (x - floor(x) is exact there; adding one
/// half first would round 0.49999999999999994 up to 1).
inline std::int64_t nearest_integer_half_up(double x) noexcept {
  const std::int64_t below = floor_to_integer(x);
  return x - static_cast<double>(below) >= 0.5 ? below + 1 : below;
}

/// Chapter 07's snap_to_subpixel(p, 8), the same rounding with the scale a constant: chapter 07
/// forms 2^bits with std::ldexp and rounds with std::floor, two library calls that cost more than
/// the rest of a small triangle's setup. A test pins that both agree.
inline ch07::SubpixelPoint snap_to_256ths(glm::dvec2 p) noexcept {
  return {nearest_integer_half_up(p.x * 256.0), nearest_integer_half_up(p.y * 256.0)};
}

/// Edge values at origin pixels are clamped to ±edge_value_limit. Across any canvas (at most
/// 2^14 pixels per side, steps at most 2^39) a value moves by less than 2^54, so a clamped edge
/// keeps its sign on every pixel and every sum the variants form stays far inside 64 bits.
inline constexpr std::int64_t edge_value_limit = std::int64_t{1} << 60;

/// One edge of a counter-clockwise triangle as a function of whole-pixel offsets (dx, dy) from the
/// setup's origin pixel: value + step_x * dx + step_y * dy. A pixel is on the inner side of the
/// edge (with the top-left rule for exact ties) exactly when that number is >= 0.
///
/// It is floor(E / 256) for chapter 07's edge function E at the pixel centre, minus 1 when the
/// edge is not top-left and E is a multiple of 256. Pixel centres sit on multiples of 256 in
/// sub-pixel units, so E moves in multiples of 256 and its remainder modulo 256 is the same for
/// every pixel: dividing it out keeps every sign and makes the steps plain vertex differences.
struct EdgeFunction {
  std::int64_t value;   ///< at the origin pixel, bias folded in
  std::int64_t step_x;  ///< change per pixel to the right
  std::int64_t step_y;  ///< change per row up

  /// The value dx pixels right of and dy rows above the origin (direct evaluation).
  std::int64_t at(std::int64_t dx, std::int64_t dy) const noexcept {
    return value + step_x * dx + step_y * dy;
  }
};

/// A triangle ready to rasterize: its three edges and the candidate pixels (chapter 07's
/// candidate_pixels, possibly clipped further). The edges' origin is (range.min.x,
/// range.min.y); the range is never empty.
struct TriangleSetup {
  /// In order around the counter-clockwise triangle: edge e ends where edge e + 1 (mod 3) starts.
  std::array<EdgeFunction, 3> edges;
  ch05::PixelBox range;
  /// The longer side of the snapped vertices' bounding box, in 1/256 pixel: bounds every edge
  /// value near the triangle (step 5 uses it to choose 32-bit lanes).
  std::int64_t vertex_extent;
  /// The middle one of the snapped vertices' three y, in 1/256 pixel: where two edges on the
  /// same side of the triangle meet, if any (step 3's walker splits its rows there).
  std::int64_t middle_y;

  /// Whether pixel (x, y) of the range is covered: all three edge values >= 0, each evaluated
  /// directly (the reference the incremental variants are tested against).
  bool covers(int x, int y) const noexcept;
};

/// Snaps the vertices (snap_to_256ths), culls zero area, orders them
/// counter-clockwise, and builds the edges at the first candidate pixel of a width x height
/// canvas. Edge values are computed in 64 bits when chapter 07's fits_64_bit_edge_functions says
/// so and in 128 bits otherwise, then clamped (edge_value_limit): beyond the 64-bit budget only the
/// setup is wider, never the per-pixel work. Empty when nothing of the canvas can be covered.
std::optional<TriangleSetup> setup_triangle(const Triangle& triangle, int width,
                                            int height) noexcept;

/// The same triangle restricted to the pixels of `clip` (a rectangle within the canvas): the
/// range shrinks and the origin moves, so edge values change by whole steps. Empty when the
/// two do not overlap. This is how the threaded variant gives each thread its rows.
std::optional<TriangleSetup> clip_setup(const TriangleSetup& setup,
                                        const ch05::PixelBox& clip) noexcept;

}  // namespace tri::ch08
