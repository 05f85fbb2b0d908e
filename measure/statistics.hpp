/// @file
/// The few statistics speed measurements need: median and spread of timed samples, geometric
/// means.
#pragma once

#include <span>
#include <vector>

namespace tri {

/// The middle and the extremes of a set of samples.
struct Spread {
  double median = 0;
  double min = 0;
  double max = 0;
};

/// Median (the mean of the two middle values for an even count), minimum and maximum: the one
/// median every benchmark of the book reports. Throws std::invalid_argument for no samples.
Spread spread_of(std::vector<double> samples);

/// The geometric mean of the positive values (others are skipped); 0 when there are none. Speeds
/// of very different scenes are averaged this way so no one scene dominates.
double geometric_mean(std::span<const double> values) noexcept;

}  // namespace tri
