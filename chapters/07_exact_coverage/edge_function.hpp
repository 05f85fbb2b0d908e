/// @file
/// The edge function on the sub-pixel grid, in 64 or 128 bits: chapter 07's exact test, which
/// chapter 08's setup evaluates once per triangle.
#pragma once

#include <cstdint>

#include "chapters/07_exact_coverage/fixed_point.hpp"
#include "chapters/07_exact_coverage/int128.hpp"

namespace tri::ch07 {

// [listing edge_function]
/// The edge function of a -> b at p: twice the signed area of (a, b, p), > 0 when p is left of
/// a -> b. Int is std::int64_t or Int128, chosen by the bit budget.
template <class Int>
Int edge_function(SubpixelPoint a, SubpixelPoint b, std::int64_t px, std::int64_t py) {
  return Int(b.x - a.x) * Int(py - a.y) - Int(b.y - a.y) * Int(px - a.x);
}
// [/listing]

}  // namespace tri::ch07
