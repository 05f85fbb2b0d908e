#include "chapters/07_exact_coverage/fixed_point.hpp"

#include "chapters/07_exact_coverage/edge_function.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace tri::ch07 {
namespace {

// [listing shifts]
// floor(a / 2^bits) and ceil(a / 2^bits) for any sign (arithmetic shift floors).
std::int64_t floor_shift(std::int64_t a, int bits) {
  return a >> bits;
}
std::int64_t ceil_shift(std::int64_t a, int bits) {
  return -((-a) >> bits);
}
// [/listing]

template <class Int>
void fill(Canvas& canvas, SubpixelPoint a, SubpixelPoint b, SubpixelPoint c, int bits,
          TieRule tie_rule, Color color) {
  const ch05::PixelBox range = candidate_pixels(a, b, c, bits, canvas.width(), canvas.height());
  if (range.empty()) return;
  // [listing biased_test]
  // A top-left edge keeps its zeros; any other edge needs strictly positive values: w - 1 >= 0.
  // The inclusive rule keeps every zero, so it biases no edge.
  const Int other_bias = tie_rule == TieRule::top_left ? -1 : 0;
  const Int bias0 = is_top_left_edge(b, c) ? 0 : other_bias;
  const Int bias1 = is_top_left_edge(c, a) ? 0 : other_bias;
  const Int bias2 = is_top_left_edge(a, b) ? 0 : other_bias;
  for (int y = range.min.y; y <= range.max.y; ++y) {
    const std::int64_t py = std::int64_t{y} << bits;
    for (int x = range.min.x; x <= range.max.x; ++x) {
      const std::int64_t px = std::int64_t{x} << bits;
      if (edge_function<Int>(b, c, px, py) + bias0 >= 0 &&
          edge_function<Int>(c, a, px, py) + bias1 >= 0 &&
          edge_function<Int>(a, b, px, py) + bias2 >= 0) {
        canvas.put_pixel(x, y, color);
      }
    }
  }
  // [/listing]
}

}  // namespace

namespace {

// The nearest integer, halves up. Not floor(v + 0.5): that sum rounds 0.49999999999999994 up to 1.
// v - floor(v) is exact, so the comparison with one half is too.
std::int64_t nearest_half_up(double v) noexcept {
  const double below = std::floor(v);
  return static_cast<std::int64_t>(v - below >= 0.5 ? below + 1.0 : below);
}

}  // namespace

// [listing snap_to_subpixel]
SubpixelPoint snap_to_subpixel(glm::dvec2 p, int bits) noexcept {
  const double scale = std::ldexp(1.0, bits);  // exact: scaling by 2^bits only moves the exponent
  return {nearest_half_up(p.x * scale), nearest_half_up(p.y * scale)};
}
// [/listing]

// [listing is_top_left_edge]
bool is_top_left_edge(SubpixelPoint a, SubpixelPoint b) noexcept {
  const bool top = a.y == b.y && b.x < a.x;
  const bool left = b.y < a.y;
  return top || left;
}
// [/listing]

// [listing fits_64_bit_edge_functions]
bool fits_64_bit_edge_functions(SubpixelPoint a, SubpixelPoint b, SubpixelPoint c) noexcept {
  constexpr std::int64_t limit = std::int64_t{1} << 29;
  for (const SubpixelPoint& p : {a, b, c}) {
    if (p.x < -limit || p.x > limit || p.y < -limit || p.y > limit) return false;
  }
  return true;
}
// [/listing]

// [listing candidate_pixels]
ch05::PixelBox candidate_pixels(SubpixelPoint a, SubpixelPoint b, SubpixelPoint c, int bits,
                                int width, int height) noexcept {
  const std::int64_t x0 = ceil_shift(std::min({a.x, b.x, c.x}), bits);
  const std::int64_t x1 = floor_shift(std::max({a.x, b.x, c.x}), bits);
  const std::int64_t y0 = ceil_shift(std::min({a.y, b.y, c.y}), bits);
  const std::int64_t y1 = floor_shift(std::max({a.y, b.y, c.y}), bits);
  return {{static_cast<int>(std::max<std::int64_t>(x0, 0)),
           static_cast<int>(std::max<std::int64_t>(y0, 0))},
          {static_cast<int>(std::min<std::int64_t>(x1, width - 1)),
           static_cast<int>(std::min<std::int64_t>(y1, height - 1))}};
}
// [/listing]

// [listing draw_triangle_fixed_point]
void draw_triangle_fixed_point(Canvas& canvas, const Triangle& triangle, Color color,
                               int subpixel_bits, TieRule tie_rule) {
  SubpixelPoint a = snap_to_subpixel(triangle[0], subpixel_bits);
  SubpixelPoint b = snap_to_subpixel(triangle[1], subpixel_bits);
  SubpixelPoint c = snap_to_subpixel(triangle[2], subpixel_bits);
  // Twice the signed area, in 128 bits so any snapped input fits: zero covers nothing, negative
  // means clockwise, which we turn around so "inside" is always "left of every edge".
  const Int128 area = edge_function<Int128>(a, b, c.x, c.y);
  if (area == 0) return;
  if (area < 0) std::swap(b, c);
  if (fits_64_bit_edge_functions(a, b, c)) {
    fill<std::int64_t>(canvas, a, b, c, subpixel_bits, tie_rule, color);
  } else {
    fill<Int128>(canvas, a, b, c, subpixel_bits, tie_rule, color);
  }
}
// [/listing]

void draw_triangle_fixed_point_inclusive(Canvas& canvas, const Triangle& triangle, Color color) {
  draw_triangle_fixed_point(canvas, triangle, color, 8, TieRule::inclusive);
}

}  // namespace tri::ch07
