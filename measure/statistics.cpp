#include "measure/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tri {

// [listing spread_of]
Spread spread_of(std::vector<double> samples) {
  if (samples.empty()) throw std::invalid_argument("spread_of needs at least one sample");
  std::sort(samples.begin(), samples.end());
  const std::size_t n = samples.size();
  const double median = n % 2 == 1 ? samples[n / 2] : (samples[n / 2 - 1] + samples[n / 2]) / 2;
  return {median, samples.front(), samples.back()};
}
// [/listing]

double geometric_mean(std::span<const double> values) noexcept {
  double log_sum = 0;
  int count = 0;
  for (const double v : values) {
    if (!(v > 0) || !std::isfinite(v)) continue;
    log_sum += std::log(v);
    ++count;
  }
  return count == 0 ? 0.0 : std::exp(log_sum / count);
}

}  // namespace tri
