/// @file
/// The eleven files of a run, rendered from one BenchReport (with the coverage rows, the scaling
/// sweeps, Blend2D's benchmark shapes and the user's path) and saved side by side.
#pragma once

#include <filesystem>
#include <optional>
#include <ostream>
#include <span>
#include <string>
#include <vector>

#include "chapters/10_speed_vs_error/blend2d_shapes.hpp"
#include "chapters/10_speed_vs_error/coverage_measure.hpp"
#include "chapters/10_speed_vs_error/measure.hpp"
#include "chapters/10_speed_vs_error/scaling.hpp"
#include "chapters/10_speed_vs_error/user_path.hpp"

namespace tri::ch10 {

/// File names: prefixed 09_ because every chapter's figures share one folder.
inline constexpr const char* csv_file_name = "10_report.csv";
inline constexpr const char* markdown_file_name = "10_report.md";
inline constexpr const char* svg_file_name = "10_speed_vs_error.svg";
inline constexpr const char* coverage_csv_file_name = "10_coverage.csv";
inline constexpr const char* coverage_svg_file_name = "10_coverage_speed_vs_error.svg";
inline constexpr const char* scaling_csv_file_name = "10_scaling.csv";
inline constexpr const char* scaling_triangles_svg_file_name = "10_scaling_triangles.svg";
inline constexpr const char* scaling_canvas_svg_file_name = "10_scaling_canvas.svg";

/// The coverage algorithms' part of a run (rule `area`).
struct CoverageReport {
  std::vector<CoverageMeasurement> rows;
  std::string peer_status;  ///< which anti-aliasing peers were measured, or why not
};

/// The contents of the eleven files.
struct ReportFiles {
  std::string csv;
  std::string markdown;  ///< every part: triangle and coverage algorithms, cost, Blend2D's shapes
  std::string svg;
  std::string coverage_csv;
  std::string coverage_svg;
  std::string scaling_csv;
  std::string scaling_triangles_svg;
  std::string scaling_canvas_svg;
  std::string blend2d_shapes_csv;
  std::string blend2d_shapes_json;  ///< bl_bench's layout
  std::string user_path_csv;        ///< `raster --bench` beside the report's time
};

/// Summarizes the report and renders the CSVs, the Markdown, the four plots and the JSON.
ReportFiles render_report(const BenchReport& report, const CoverageReport& coverage = {},
                          std::span<const ScalingPoint> scaling = {},
                          std::span<const ShapeRate> shapes = {},
                          const std::optional<UserPathComparison>& user_path = std::nullopt);

/// The paths of the eleven files in folder, to check before measuring.
std::vector<std::filesystem::path> report_paths(const std::filesystem::path& folder);

/// Writes the eleven files into folder as one set (all replaced, or none when one fails) and logs
/// each path.
void save_report(const std::filesystem::path& folder, const BenchReport& report,
                 const CoverageReport& coverage, std::span<const ScalingPoint> scaling,
                 std::span<const ShapeRate> shapes,
                 const std::optional<UserPathComparison>& user_path, std::ostream& log);

}  // namespace tri::ch10
