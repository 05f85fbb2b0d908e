/// @file
/// Logarithmic axes for the plot: whole decades, and for the error axis a separate floor where
/// an error of exactly 0 ("exact") is drawn, since log 0 does not exist.
#pragma once

#include <span>
#include <string>

namespace tri {

/// The decades 10^low .. 10^high mapped linearly in log10 onto positions low_position ..
/// high_position (high_position may be smaller, as for an SVG y axis that grows downward).
struct LogScale {
  int low_decade = 0;
  int high_decade = 1;  ///< > low_decade
  double low_position = 0;
  double high_position = 1;

  /// Where a value goes; values outside the decades, 0 and negatives are clamped to the ends.
  double position(double value) const noexcept;
};

/// A range of whole decades, 10^low .. 10^high.
struct DecadeRange {
  int low = 0;
  int high = 1;
};

/// The smallest whole decades [low, high], high > low, that hold every positive finite value;
/// {0, 1} when there is none.
DecadeRange decades_covering(std::span<const double> values) noexcept;

/// The error axis: a log scale for positive rates, and a floor before its low end where 0 goes.
struct ErrorAxis {
  LogScale scale;
  double zero_position = 0;  ///< where an exact algorithm (error 0) is drawn, labelled "exact"

  double position(double error_rate) const noexcept {
    return error_rate > 0 ? scale.position(error_rate) : zero_position;
  }
};

/// "10ⁿ": 10 with k as a superscript exponent.
std::string power_of_ten_label(int k);

/// The label of the decade 10^k: a plain number for -3 <= k <= 5 ("0.001", "100000"), "10ⁿ"
/// with a superscript exponent beyond.
std::string decade_label(int k);

}  // namespace tri
