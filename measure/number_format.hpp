/// @file
/// Numbers as the report's CSV, tables and plots write them (and the Markdown the listings tool
/// fills from a snapshot, so the book shows them the same way).
#pragma once

#include <string>

namespace tri {

/// A number with `significant` significant digits, "%g" style.
std::string format_number(double value, int significant = 4);

/// A rate with a k/M/G suffix and 3 significant digits, e.g. "12.3 M"; "–" for 0.
std::string human_rate(double per_second);

/// A speed in Mpix/s for a table: whole numbers from 100 up ("1560"), else 3 significant digits.
std::string format_mpix(double mpix_per_s);

/// An error rate for a table: "0 (exact)" when no pixel differs, else 3 significant digits.
std::string format_error_rate(double error_rate);

}  // namespace tri
