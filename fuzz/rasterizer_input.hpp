/// @file
/// How fuzz_rasterizers turns arbitrary bytes into a drawing job: which registered algorithm, how
/// big a canvas, and up to four coloured triangles whose vertices are either raw doubles (so NaN,
/// infinities, huge and subnormal values arise) or "interesting" values built from a table.
///
/// Byte layout (every input decodes; missing bytes read as zero):
///
///     byte 0        algorithm selector (taken modulo the registry's size)
///     byte 1        canvas width - 1, modulo 64   (so 1..64)
///     byte 2        canvas height - 1, modulo 64  (so 1..64)
///     then 1..4 triangle records, one started for every byte left:
///       byte 0      encoding: even = raw doubles, odd = interesting values
///       bytes 1-3   colour r, g, b (alpha is 255)
///       raw:        6 x 8 bytes: x0 y0 x1 y1 x2 y2, little-endian IEEE 754 doubles
///       interesting 6 x 3 bytes: base (index modulo the table), whole (signed), fraction:
///                   the coordinate is base + whole + fraction / 256
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "common/scene.hpp"
#include "common/triangle_algorithm.hpp"

namespace tri::fuzz {

/// A small canvas keeps one execution fast, so the fuzzer tries many inputs per second.
inline constexpr int max_fuzz_canvas_side = 64;

/// More triangles per input only matter for the batch entry point; four show drawing order.
inline constexpr std::size_t max_fuzz_triangles = 4;

/// The bases of the interesting-value encoding, in table order. Each names a value that broke, or
/// could break, a rasterizer: limits of the scene format, of float, of int and of double.
enum class Base : std::uint8_t {
  zero,
  limit,                 ///< 2^30, the largest coordinate a scene allows
  minus_limit,           ///< -2^30
  ten_million,           ///< 1e7, the hard cases' far vertex
  minus_ten_million,     ///< -1e7
  float_gap,             ///< 2^24 + 1, the first integer a float cannot hold
  minus_float_gap,       ///< -(2^24 + 1)
  half_limit,            ///< 2^29, where fixed-point switches to 128-bit edge functions
  minus_half_limit,      ///< -2^29
  beyond_int,            ///< 2^31, just past int's range
  canvas_edge,           ///< 64, one past the largest canvas
  almost_half,           ///< 0.49999999999999994, where floor(x + 0.5) rounds the wrong way
  subnormal,             ///< 1e-310
  largest_double,        ///< the largest finite double
  minus_largest_double,  ///< its negative
  not_a_number,          ///< quiet NaN
  infinity,              ///< +inf
  minus_infinity,        ///< -inf
  minus_zero,            ///< -0.0
  count                  ///< the table's size (not a base)
};

/// The value of a base.
double base_value(Base base) noexcept;

/// One coordinate in the interesting-value encoding.
struct InterestingValue {
  Base base = Base::zero;
  std::int8_t whole = 0;
  std::uint8_t fraction = 0;  ///< in 1/256ths of a pixel
};

/// base + whole + fraction / 256, summed in that order (NaN and infinities stay what they are).
double interesting_value(InterestingValue value) noexcept;

/// What one input asks for.
struct RasterizerInput {
  std::size_t algorithm_selector = 0;
  int width = 1;
  int height = 1;
  std::vector<SceneTriangle> triangles;  ///< 1..max_fuzz_triangles, possibly invalid
};

/// Decodes any bytes (see the layout above). Never fails.
RasterizerInput decode_rasterizer_input(std::span<const std::uint8_t> bytes);

/// Builds inputs byte by byte in the layout above: how the seed corpus is written.
class RasterizerInputWriter {
 public:
  /// Starts an input for the algorithm selector and a width x height canvas (1..64 each).
  RasterizerInputWriter(std::uint8_t algorithm_selector, int width, int height);

  /// Appends a triangle whose six coordinates are stored as raw doubles.
  RasterizerInputWriter& raw(const Triangle& vertices, Color color);

  /// Appends a triangle whose six coordinates (x0 y0 x1 y1 x2 y2) use the interesting table.
  RasterizerInputWriter& interesting(const std::array<InterestingValue, 6>& coordinates,
                                     Color color);

  const std::vector<std::uint8_t>& bytes() const noexcept { return bytes_; }

 private:
  std::vector<std::uint8_t> bytes_;
};

}  // namespace tri::fuzz
