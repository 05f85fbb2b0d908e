/// @file
/// 10_report.csv: every measurement of a run, one row per (algorithm, scene).
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "chapters/10_speed_vs_error/measure.hpp"
#include "measure/number_format.hpp"

namespace tri::ch10 {

/// The header line's column names, in order.
std::span<const std::string_view> csv_columns() noexcept;

/// The header and one line per measurement. Text fields never contain commas (names are
/// identifiers, the grid is "integer" or "1/256").
std::string to_csv(std::span<const Measurement> rows);

}  // namespace tri::ch10
