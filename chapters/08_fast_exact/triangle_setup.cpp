#include "chapters/08_fast_exact/triangle_setup.hpp"

#include <algorithm>
#include <utility>

#include "chapters/07_exact_coverage/edge_function.hpp"

namespace tri::ch08 {
namespace {

using ch07::edge_function;
using ch07::SubpixelPoint;

// [listing make_edge]
// The edge a -> b at the origin pixel (origin_x, origin_y), in whole-pixel units.
template <class Int>
EdgeFunction make_edge(SubpixelPoint a, SubpixelPoint b, std::int64_t origin_x,
                       std::int64_t origin_y) {
  const Int e = edge_function<Int>(a, b, origin_x << subpixel_bits, origin_y << subpixel_bits);
  Int value = e >> subpixel_bits;  // floor(e / 256): the shift floors negatives too
  // A non-top-left edge must reject exact zeros (e >= 1); with no remainder that is value >= 1.
  // Asked in this order because a remainder of zero is rare off the integer grid.
  if ((e & ((Int(1) << subpixel_bits) - 1)) == 0 && !ch07::is_top_left_edge(a, b)) value -= 1;
  // The vertex differences fit in 40 bits, so the steps are exact in 64 bits.
  EdgeFunction edge{0, -(b.y - a.y), b.x - a.x};
  if constexpr (sizeof(Int) == sizeof(std::int64_t)) {
    edge.value = value;  // within chapter 07's 64-bit budget |e| < 2^62: no clamp needed
  } else if (value >= Int(edge_value_limit)) {
    edge = {edge_value_limit, 0, 0};  // passes on the whole canvas
  } else if (value <= Int(-edge_value_limit)) {
    edge = {-edge_value_limit, 0, 0};  // fails on the whole canvas
  } else {
    edge.value = static_cast<std::int64_t>(value);
  }
  return edge;
}
// [/listing]

template <class Int>
std::optional<TriangleSetup> setup(SubpixelPoint a, SubpixelPoint b, SubpixelPoint c,
                                   const ch05::PixelBox& range) {
  // Twice the signed area: zero covers nothing, negative is clockwise and gets turned around.
  const Int area = edge_function<Int>(a, b, c.x, c.y);
  if (area == 0) return std::nullopt;
  if (area < 0) std::swap(b, c);
  TriangleSetup s{{make_edge<Int>(b, c, range.min.x, range.min.y),
                   make_edge<Int>(c, a, range.min.x, range.min.y),
                   make_edge<Int>(a, b, range.min.x, range.min.y)},
                  range,
                  std::max(std::max({a.x, b.x, c.x}) - std::min({a.x, b.x, c.x}),
                           std::max({a.y, b.y, c.y}) - std::min({a.y, b.y, c.y})),
                  std::max(std::min(a.y, b.y), std::min(std::max(a.y, b.y), c.y))};
  if constexpr (sizeof(Int) > sizeof(std::int64_t)) {
    for (const EdgeFunction& edge : s.edges) {
      if (edge.value <= -edge_value_limit) return std::nullopt;  // fails on the whole canvas
    }
  }
  return s;
}

}  // namespace

bool TriangleSetup::covers(int x, int y) const noexcept {
  const std::int64_t dx = x - range.min.x, dy = y - range.min.y;
  return edges[0].at(dx, dy) >= 0 && edges[1].at(dx, dy) >= 0 && edges[2].at(dx, dy) >= 0;
}

// [listing setup_triangle]
std::optional<TriangleSetup> setup_triangle(const Triangle& triangle, int width,
                                            int height) noexcept {
  const SubpixelPoint a = snap_to_256ths(triangle[0]);
  const SubpixelPoint b = snap_to_256ths(triangle[1]);
  const SubpixelPoint c = snap_to_256ths(triangle[2]);
  const ch05::PixelBox range = ch07::candidate_pixels(a, b, c, subpixel_bits, width, height);
  if (range.empty()) return std::nullopt;
  if (ch07::fits_64_bit_edge_functions(a, b, c)) return setup<std::int64_t>(a, b, c, range);
  return setup<Int128>(a, b, c, range);
}
// [/listing]

std::optional<TriangleSetup> clip_setup(const TriangleSetup& setup,
                                        const ch05::PixelBox& clip) noexcept {
  const ch05::PixelBox& r = setup.range;
  const ch05::PixelBox clipped{{std::max(r.min.x, clip.min.x), std::max(r.min.y, clip.min.y)},
                               {std::min(r.max.x, clip.max.x), std::min(r.max.y, clip.max.y)}};
  if (clipped.empty()) return std::nullopt;
  TriangleSetup s = setup;
  s.range = clipped;
  for (EdgeFunction& edge : s.edges) {
    edge.value = edge.at(clipped.min.x - r.min.x, clipped.min.y - r.min.y);
  }
  return s;
}

}  // namespace tri::ch08
