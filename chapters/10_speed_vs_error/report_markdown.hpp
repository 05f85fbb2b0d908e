/// @file
/// 10_report.md: the machine, the setting, and one table row per algorithm.
#pragma once

#include <span>
#include <string>

#include "chapters/10_speed_vs_error/measure.hpp"
#include "chapters/10_speed_vs_error/summary.hpp"

namespace tri::ch10 {

/// The whole Markdown report: machine, setting, ceilings, then the table of summaries.
std::string to_markdown(const BenchReport& report, std::span<const AlgorithmSummary> summaries);

}  // namespace tri::ch10
