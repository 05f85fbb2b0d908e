/// @file
/// The three files of a run, rendered from one BenchReport and saved side by side.
#pragma once

#include <string>

#include "figures.hpp"
#include "measure.hpp"

namespace tri::ch09 {

/// File names: prefixed 09_ because every chapter's figures share one folder.
inline constexpr const char* csv_file_name = "09_report.csv";
inline constexpr const char* markdown_file_name = "09_report.md";
inline constexpr const char* svg_file_name = "09_speed_vs_error.svg";

/// The contents of the three files.
struct ReportFiles {
  std::string csv;
  std::string markdown;
  std::string svg;
};

/// Summarizes the report and renders the CSV, the Markdown table and the plot.
ReportFiles render_report(const BenchReport& report);

/// Writes the three files through the figure writer (which logs each path).
void save_report(FigureWriter& figures, const BenchReport& report);

}  // namespace tri::ch09
