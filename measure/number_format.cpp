#include "measure/number_format.hpp"

#include <cmath>
#include <cstdio>

namespace tri {

std::string format_number(double value, int significant) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*g", significant, value);
  return text;
}

std::string human_rate(double per_second) {
  if (!(per_second > 0)) return "–";
  if (per_second >= 1e9) return format_number(per_second / 1e9, 3) + " G";
  if (per_second >= 1e6) return format_number(per_second / 1e6, 3) + " M";
  if (per_second >= 1e3) return format_number(per_second / 1e3, 3) + " k";
  return format_number(per_second, 3);
}

std::string format_mpix(double mpix_per_s) {
  if (mpix_per_s >= 100) return std::to_string(static_cast<long long>(std::llround(mpix_per_s)));
  return format_number(mpix_per_s, 3);
}

std::string format_error_rate(double error_rate) {
  if (error_rate == 0) return "0 (exact)";
  return format_number(error_rate, 3);
}

}  // namespace tri
