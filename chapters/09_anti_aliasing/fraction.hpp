/// @file
/// Exact fractions for the area oracle: a 128-bit numerator and denominator, always reduced, with
/// every operation checked for overflow (an overflow throws; it never wraps).
#pragma once

#include <cstdint>
#include <string>

#include "chapters/07_exact_coverage/int128.hpp"

namespace tri::ch09 {

/// A fraction numerator / denominator in lowest terms, denominator > 0.
class Fraction {
 public:
  Fraction() = default;
  /// The whole number n.
  Fraction(std::int64_t n) : numerator_(n) {}  // NOLINT: a whole number is a fraction
  /// n / d reduced; d must not be 0 (throws std::domain_error).
  Fraction(Int128 n, Int128 d);

  Int128 numerator() const noexcept { return numerator_; }
  Int128 denominator() const noexcept { return denominator_; }
  /// The nearest double (exact for the small fractions of the tests).
  double to_double() const noexcept;
  /// "n/d" in decimal, for test messages.
  std::string text() const;

  friend Fraction operator+(Fraction a, Fraction b);
  friend Fraction operator-(Fraction a, Fraction b);
  friend Fraction operator*(Fraction a, Fraction b);
  friend Fraction operator/(Fraction a, Fraction b);
  friend bool operator==(const Fraction& a, const Fraction& b) = default;
  friend bool operator<(Fraction a, Fraction b);

 private:
  Int128 numerator_ = 0;
  Int128 denominator_ = 1;
};

}  // namespace tri::ch09
