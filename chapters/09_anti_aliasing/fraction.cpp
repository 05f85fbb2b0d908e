#include "chapters/09_anti_aliasing/fraction.hpp"

#include <stdexcept>

namespace tri::ch09 {
namespace {

Int128 checked_multiply(Int128 a, Int128 b) {
  Int128 product = 0;
  if (__builtin_mul_overflow(a, b, &product)) {
    throw std::overflow_error("exact area: a fraction outgrew 128 bits (coordinates too large)");
  }
  return product;
}

Int128 checked_add(Int128 a, Int128 b) {
  Int128 sum = 0;
  if (__builtin_add_overflow(a, b, &sum)) {
    throw std::overflow_error("exact area: a fraction outgrew 128 bits (coordinates too large)");
  }
  return sum;
}

Int128 magnitude(Int128 v) noexcept {
  return v < 0 ? -v : v;
}

Int128 greatest_common_divisor(Int128 a, Int128 b) noexcept {
  a = magnitude(a);
  b = magnitude(b);
  while (b != 0) {
    const Int128 r = a % b;
    a = b;
    b = r;
  }
  return a;
}

}  // namespace

Fraction::Fraction(Int128 n, Int128 d) {
  if (d == 0) throw std::domain_error("a fraction with denominator 0");
  if (d < 0) {
    n = -n;
    d = -d;
  }
  const Int128 g = greatest_common_divisor(n, d);
  numerator_ = g > 1 ? n / g : n;
  denominator_ = g > 1 ? d / g : d;
}

double Fraction::to_double() const noexcept {
  return static_cast<double>(numerator_) / static_cast<double>(denominator_);
}

std::string Fraction::text() const {
  const auto decimal = [](Int128 v) {
    if (v == 0) return std::string("0");
    std::string digits;
    const bool negative = v < 0;
    for (Int128 m = magnitude(v); m > 0; m /= 10) digits.insert(digits.begin(), char('0' + m % 10));
    return negative ? "-" + digits : digits;
  };
  return decimal(numerator_) + "/" + decimal(denominator_);
}

Fraction operator+(Fraction a, Fraction b) {
  // Over the least common denominator, so the numbers grow no more than they must.
  const Int128 g = greatest_common_divisor(a.denominator_, b.denominator_);
  const Int128 left = checked_multiply(a.numerator_, b.denominator_ / g);
  const Int128 right = checked_multiply(b.numerator_, a.denominator_ / g);
  return {checked_add(left, right), checked_multiply(a.denominator_ / g, b.denominator_)};
}

Fraction operator-(Fraction a, Fraction b) {
  return a + Fraction(-b.numerator_, b.denominator_);
}

Fraction operator*(Fraction a, Fraction b) {
  // Cross-reduce first: (a/b)(c/d) = (a/g1)(c/g2) / ((b/g2)(d/g1)).
  const Int128 g1 = greatest_common_divisor(a.numerator_, b.denominator_);
  const Int128 g2 = greatest_common_divisor(b.numerator_, a.denominator_);
  const Int128 n1 = g1 > 1 ? a.numerator_ / g1 : a.numerator_;
  const Int128 d2 = g1 > 1 ? b.denominator_ / g1 : b.denominator_;
  const Int128 n2 = g2 > 1 ? b.numerator_ / g2 : b.numerator_;
  const Int128 d1 = g2 > 1 ? a.denominator_ / g2 : a.denominator_;
  return {checked_multiply(n1, n2), checked_multiply(d1, d2)};
}

Fraction operator/(Fraction a, Fraction b) {
  return a * Fraction(b.denominator_, b.numerator_);
}

bool operator<(Fraction a, Fraction b) {
  return (a - b).numerator_ < 0;
}

}  // namespace tri::ch09
