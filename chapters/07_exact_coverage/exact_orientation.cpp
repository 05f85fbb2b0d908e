#include "chapters/07_exact_coverage/exact_orientation.hpp"
#include "chapters/07_exact_coverage/int128.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace tri::ch07 {
namespace {

// A finite double as mantissa * 2^exponent with an integer mantissa below 2^53 in magnitude.
struct Dyadic {
  std::int64_t mantissa;
  int exponent;
};

Dyadic decompose(double x) {
  if (x == 0.0) return {0, 0};
  int exponent = 0;
  const double fraction =
      std::frexp(x, &exponent);  // x = fraction * 2^exponent, |fraction| in [0.5, 1)
  return {static_cast<std::int64_t>(std::ldexp(fraction, 53)), exponent - 53};
}

// One of the six terms: sign * mantissa * 2^exponent, |mantissa| < 2^106.
struct Term {
  Int128 mantissa;
  int exponent;
};

Term product(double x, double y, int sign) {
  const Dyadic dx = decompose(x);
  const Dyadic dy = decompose(y);
  return {Int128{dx.mantissa} * dy.mantissa * sign, dx.exponent + dy.exponent};
}

// Exponents of products span at most [-2148, 1942]; with 106-bit mantissas and carries the exact
// sum needs under 4200 bits.
constexpr int max_limbs = 68;

// A two's-complement integer of `limbs` 64-bit limbs, least significant first.
class WideInteger {
 public:
  explicit WideInteger(int limbs) : limbs_(limbs) { digits_.fill(0); }

  // Adds mantissa * 2^shift.
  void add(Int128 mantissa, int shift) {
    const bool negative = mantissa < 0;
    const UInt128 magnitude = negative ? UInt128(-(mantissa + 1)) + 1 : UInt128(mantissa);
    const int limb = shift / 64;
    const int bit = shift % 64;
    // magnitude << bit spans at most three limbs.
    std::array<std::uint64_t, 3> part{};
    part[0] = static_cast<std::uint64_t>(magnitude << bit);
    part[1] = static_cast<std::uint64_t>((bit == 0 ? magnitude >> 64 : magnitude >> (64 - bit)));
    part[2] = bit == 0 ? 0 : static_cast<std::uint64_t>((magnitude >> 64) >> (64 - bit));
    if (negative) {
      subtract_at(limb, part);
    } else {
      add_at(limb, part);
    }
  }

  int sign() const {
    if (digits_[limbs_ - 1] >> 63) return -1;
    for (int i = 0; i < limbs_; ++i) {
      if (digits_[i] != 0) return 1;
    }
    return 0;
  }

 private:
  void add_at(int limb, const std::array<std::uint64_t, 3>& part) {
    std::uint64_t carry = 0;
    for (int i = limb; i < limbs_; ++i) {
      const std::uint64_t addend = i - limb < 3 ? part[i - limb] : 0;
      if (addend == 0 && carry == 0 && i - limb >= 3) break;
      const UInt128 sum = UInt128(digits_[i]) + addend + carry;
      digits_[i] = static_cast<std::uint64_t>(sum);
      carry = static_cast<std::uint64_t>(sum >> 64);
    }
  }

  void subtract_at(int limb, const std::array<std::uint64_t, 3>& part) {
    std::uint64_t borrow = 0;
    for (int i = limb; i < limbs_; ++i) {
      const std::uint64_t subtrahend = i - limb < 3 ? part[i - limb] : 0;
      if (subtrahend == 0 && borrow == 0 && i - limb >= 3) break;
      const std::uint64_t d = digits_[i];
      const std::uint64_t result = d - subtrahend - borrow;
      borrow = (d < subtrahend || (d == subtrahend && borrow)) ? 1 : 0;
      digits_[i] = result;
    }
  }

  int limbs_;
  std::array<std::uint64_t, max_limbs> digits_;
};

}  // namespace

// [listing exact_orientation_slow_path]
int exact_orientation_slow_path(glm::dvec2 a, glm::dvec2 b, glm::dvec2 p) noexcept {
  // (bx - ax)(py - ay) - (by - ay)(px - ax) with ax*ay - ay*ax cancelled: six products.
  const std::array<Term, 6> terms{product(b.x, p.y, +1), product(b.x, a.y, -1),
                                  product(a.x, p.y, -1), product(b.y, p.x, -1),
                                  product(b.y, a.x, +1), product(a.y, p.x, +1)};
  int lowest = 1 << 30;
  int highest = -(1 << 30);
  for (const Term& t : terms) {
    if (t.mantissa == 0) continue;
    lowest = std::min(lowest, t.exponent);
    highest = std::max(highest, t.exponent);
  }
  if (lowest > highest) return 0;  // every product is zero
  // Room for the largest shifted mantissa (106 bits), six carries and a sign bit.
  const int bits = highest - lowest + 106 + 4;
  WideInteger sum(std::min(max_limbs, bits / 64 + 1));
  for (const Term& t : terms) {
    if (t.mantissa != 0) sum.add(t.mantissa, t.exponent - lowest);
  }
  return sum.sign();
}
// [/listing]

// [listing exact_orientation]
int exact_orientation(glm::dvec2 a, glm::dvec2 b, glm::dvec2 p) noexcept {
  const double left = (b.x - a.x) * (p.y - a.y);
  const double right = (b.y - a.y) * (p.x - a.x);
  const double determinant = left - right;
  const double magnitude = std::abs(left) + std::abs(right);
  // Shewchuk's bound for this evaluation order; valid while nothing overflows and the products
  // are far above the subnormal range (below it their rounding error is no longer relative).
  constexpr double epsilon = 0x1p-53;
  constexpr double error_factor = (3.0 + 16.0 * epsilon) * epsilon;
  if (std::isfinite(magnitude) && magnitude >= 0x1p-900) {
    const double bound = error_factor * magnitude;
    if (determinant > bound) return 1;
    if (-determinant > bound) return -1;
  }
  return exact_orientation_slow_path(a, b, p);
}
// [/listing]

}  // namespace tri::ch07
