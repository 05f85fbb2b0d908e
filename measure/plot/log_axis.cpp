#include "measure/plot/log_axis.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>

#include "measure/number_format.hpp"

namespace tri {

// [listing log_position]
double LogScale::position(double value) const noexcept {
  const double low = low_decade;
  const double high = std::max(high_decade, low_decade + 1);  // never a zero-width scale
  const double decade = value > 0 ? std::clamp(std::log10(value), low, high) : low;
  return low_position + (decade - low) / (high - low) * (high_position - low_position);
}
// [/listing]

DecadeRange decades_covering(std::span<const double> values) noexcept {
  double smallest = 0, largest = 0;
  bool any = false;
  for (const double v : values) {
    if (!(v > 0) || !std::isfinite(v)) continue;
    smallest = any ? std::min(smallest, v) : v;
    largest = any ? std::max(largest, v) : v;
    any = true;
  }
  if (!any) return {};
  const int low = static_cast<int>(std::floor(std::log10(smallest)));
  const int high = static_cast<int>(std::ceil(std::log10(largest)));
  return {low, std::max(high, low + 1)};
}

std::string power_of_ten_label(int k) {
  static constexpr std::array<const char*, 10> digits{"⁰", "¹", "²", "³", "⁴",
                                                      "⁵", "⁶", "⁷", "⁸", "⁹"};
  std::string text = k < 0 ? "10⁻" : "10";
  for (const char c : std::to_string(std::abs(k))) text += digits[c - '0'];
  return text;
}

std::string decade_label(int k) {
  if (k >= -3 && k <= 5) return format_number(std::pow(10.0, k), 6);
  return power_of_ten_label(k);
}

}  // namespace tri
