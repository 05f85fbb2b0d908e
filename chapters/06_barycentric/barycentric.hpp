/// @file
/// Steps 2 and 3: the barycentric coordinates of a pixel from one 3-D cross product, the guard
/// against a zero area, and the inside test that reads the three weights.
#pragma once

#include <cmath>
#include <concepts>
#include <cstdint>
#include <limits>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace tri::ch06 {

/// Three barycentric weights (of A, B and C, in that order) in the arithmetic Scalar.
template <std::floating_point Scalar>
using Weights = glm::vec<3, Scalar>;

// [listing cross_of_rows]
/// The cross product of the x row (AB.x, AC.x, PA.x) and the y row (AB.y, AC.y, PA.y).
/// Every weight comes out of it: P = A + s·AB + t·AC exactly when (s, t, 1) is perpendicular to
/// both rows, so (s, t, 1) is u / u.z; and u.z = AB × AC is twice the signed area of ABC. The
/// differences are taken in 64-bit integers and only then converted to Scalar (no int overflow
/// within ±2^30); the products are Scalar, which is where float loses digits.
template <std::floating_point Scalar>
glm::vec<3, Scalar> cross_of_rows(glm::ivec2 a, glm::ivec2 b, glm::ivec2 c, glm::ivec2 p) noexcept {
  const auto difference = [](int to, int from) {
    return static_cast<Scalar>(static_cast<std::int64_t>(to) - from);
  };
  const glm::vec<3, Scalar> x_row(difference(b.x, a.x), difference(c.x, a.x), difference(a.x, p.x));
  const glm::vec<3, Scalar> y_row(difference(b.y, a.y), difference(c.y, a.y), difference(a.y, p.y));
  return {x_row.y * y_row.z - x_row.z * y_row.y, x_row.z * y_row.x - x_row.x * y_row.z,
          x_row.x * y_row.y - x_row.y * y_row.x};
}
// [/listing]

/// What the guarded version returns for a zero-area triangle: a negative weight, so the inside
/// test rejects every pixel.
template <std::floating_point Scalar>
inline constexpr Weights<Scalar> degenerate_weights{-1, 1, 1};

// [listing barycentric]
/// The barycentric weights (wA, wB, wC) of pixel p in triangle abc: p = wA·a + wB·b + wC·c and
/// wA + wB + wC = 1. Either winding works, since the area's sign divides out. A zero-area
/// triangle returns degenerate_weights instead of dividing by zero.
template <std::floating_point Scalar>
Weights<Scalar> barycentric(glm::ivec2 a, glm::ivec2 b, glm::ivec2 c, glm::ivec2 p) noexcept {
  const glm::vec<3, Scalar> u = cross_of_rows<Scalar>(a, b, c, p);
  // With integer vertices u.z is a whole number in both float and double, so below 1 means 0.
  if (std::abs(u.z) < Scalar(1)) return degenerate_weights<Scalar>;
  return {Scalar(1) - (u.x + u.y) / u.z, u.x / u.z, u.y / u.z};
}
// [/listing]

// [listing barycentric_unguarded]
/// The same weights without the guard, kept only to show what the guard prevents: for a
/// zero-area triangle u.z is 0 and the weights become ±infinity or NaN (IEEE 754 division).
/// Never registered as an algorithm.
template <std::floating_point Scalar>
Weights<Scalar> barycentric_unguarded(glm::ivec2 a, glm::ivec2 b, glm::ivec2 c,
                                      glm::ivec2 p) noexcept {
  static_assert(std::numeric_limits<Scalar>::is_iec559, "division by zero must give inf/NaN");
  const glm::vec<3, Scalar> u = cross_of_rows<Scalar>(a, b, c, p);
  return {Scalar(1) - (u.x + u.y) / u.z, u.x / u.z, u.y / u.z};
}
// [/listing]

// [listing is_inside]
/// The articles' inside test: reject the pixel if any weight is below zero. A weight of exactly 0
/// (a pixel on an edge) passes. So does NaN, because every comparison with NaN is false.
template <std::floating_point Scalar>
bool is_inside(const Weights<Scalar>& weights) noexcept {
  return !(weights.x < 0 || weights.y < 0 || weights.z < 0);
}
// [/listing]

}  // namespace tri::ch06
