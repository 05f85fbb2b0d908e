/// @file
/// 10_report.md: the machine, the setting, and one table row per algorithm.
#pragma once

#include <span>
#include <string>

#include "chapters/10_speed_vs_error/measure.hpp"
#include "chapters/10_speed_vs_error/summary.hpp"

namespace tri::ch10 {

/// A rate with a k/M/G suffix and 3 significant digits, e.g. "12.3 M"; "–" for 0.
std::string human_rate(double per_second);

/// A speed in Mpix/s for a table: whole numbers from 100 up ("1560"), else 3 significant digits.
std::string format_mpix(double mpix_per_s);

/// The whole Markdown report: machine, setting, ceilings, then the table of summaries.
std::string to_markdown(const BenchReport& report, std::span<const AlgorithmSummary> summaries);

}  // namespace tri::ch10
