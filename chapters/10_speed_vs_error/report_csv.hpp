/// @file
/// 10_report.csv: every measurement of a run, one row per (algorithm, scene); and the table and
/// row writer that the chapter's other CSV files are written with too.
#pragma once

#include <ostream>
#include <span>
#include <sstream>
#include <string>
#include <string_view>
#include <tuple>

#include "chapters/10_speed_vs_error/measure.hpp"
#include "measure/number_format.hpp"
#include "measure/timing.hpp"

namespace tri::ch10 {

/// Writes one CSV line: the fields in order, separated by commas, each as the stream writes it.
template <typename... Fields>
void write_csv_row(std::ostream& csv, const Fields&... fields) {
  const char* separator = "";
  ((csv << separator << fields, separator = ","), ...);
  csv << '\n';
}

/// A whole CSV file: the header line, then one line per row with the fields fields_of(row) returns
/// as a tuple.
template <typename Row, typename FieldsOf>
std::string csv_table(std::string_view header, std::span<const Row> rows, FieldsOf fields_of) {
  std::ostringstream csv;
  csv << header << '\n';
  for (const Row& row : rows) {
    std::apply([&csv](const auto&... fields) { write_csv_row(csv, fields...); }, fields_of(row));
  }
  return csv.str();
}

/// The median, fastest and slowest seconds of a timing as three CSV columns, six significant
/// digits each (as the report, coverage and scaling CSV files write them).
std::string seconds_columns(const Timing& timing);

/// A free-text field (a reason, a problem) as RFC 4180 writes it: in double quotes, each quote
/// doubled, so commas and line breaks stay inside the field.
std::string quoted_text(std::string_view text);

/// "WIDTHxHEIGHT", the canvas column.
std::string canvas_column(int width, int height);

/// The header line's column names, in order.
std::span<const std::string_view> csv_columns() noexcept;

/// The header and one line per measurement. Text fields never contain commas (names are
/// identifiers, the grid is "integer" or "1/256").
std::string to_csv(std::span<const Measurement> rows);

}  // namespace tri::ch10
