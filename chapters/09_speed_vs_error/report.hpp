/// @file
/// The three files of a run, rendered from one BenchReport and saved side by side.
#pragma once

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "chapters/09_speed_vs_error/measure.hpp"

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

/// The paths of the three files in folder, to check before measuring.
std::vector<std::filesystem::path> report_paths(const std::filesystem::path& folder);

/// Writes the three files into folder as one set (all replaced, or none when one fails) and logs
/// each path.
void save_report(const std::filesystem::path& folder, const BenchReport& report, std::ostream& log);

}  // namespace tri::ch09
