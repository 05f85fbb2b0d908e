/// @file
/// The user's path in the report: one algorithm on one of the run's scenes timed by `raster
/// --bench`, run as a program on the scene written as a file, beside the report's own time for the
/// same draw, so a reader sees whether timing `raster` as a user would gives the report's numbers.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <ostream>
#include <span>
#include <string>
#include <string_view>

#include "chapters/10_speed_vs_error/measure.hpp"
#include "chapters/10_speed_vs_error/suites.hpp"
#include "common/triangle_algorithm.hpp"

namespace tri::ch10 {

inline constexpr const char* user_path_csv_file_name = "10_user_path.csv";

/// What `raster --bench` printed (docs/DESIGN.md section 9).
struct RasterBench {
  double preparation_seconds = 0;  ///< its preparation_seconds= line
  std::size_t triangles = 0;
  long long frames = 0;
  double frame_seconds = 0;  ///< the median frame (`seconds=`)
};

/// Reads the two lines `raster --bench` prints; throws std::runtime_error naming the first value
/// that is missing or not a number.
RasterBench parse_raster_bench(std::string_view output);

/// One algorithm on one scene timed twice: by the report, and by `raster --bench`.
struct UserPathComparison {
  std::string algorithm;
  std::string scene;
  std::string grid;
  std::size_t triangles = 0;
  double report_seconds = 0;          ///< the report's median draw of the prepared scene
  std::string command;                ///< the command run, the scene file named by its scene
  std::optional<RasterBench> raster;  ///< empty when `raster` could not be run or read
  std::string problem;                ///< why not, one line (empty when measured)

  /// raster's median frame over the report's median draw; 0 when raster was not measured.
  double ratio() const noexcept;
};

/// The algorithm the comparison times: the selected one the report's sweeps follow (its role),
/// else the first selected; nullptr when none was selected.
const TriangleAlgorithm* user_path_algorithm(std::span<const TriangleAlgorithm> algorithms);

/// How many frames `raster --bench` draws: about budget_seconds of the report's median draw,
/// from 21 to 2001.
long long user_path_frames(double report_seconds, double budget_seconds) noexcept;

/// Times the algorithm's first row of the report (the run's first scene) with `raster` (the
/// program at raster_program) on that scene written to a temporary file, for about budget_seconds
/// of frames; one progress line. A raster that is missing, fails or prints something else is
/// written into problem, not thrown. Nothing when the report has no row of the algorithm.
std::optional<UserPathComparison> measure_user_path(const BenchReport& report,
                                                    const TriangleAlgorithm& algorithm,
                                                    std::span<const SuiteScene> scenes,
                                                    const std::filesystem::path& raster_program,
                                                    double budget_seconds, std::ostream& progress);

/// The Markdown section "The user's path" (empty without a comparison): both times and their
/// ratio, or why `raster` was not measured.
std::string user_path_markdown(const std::optional<UserPathComparison>& comparison);

/// A header and one line (none without a comparison); the problem is one quoted field.
std::string user_path_csv(const std::optional<UserPathComparison>& comparison);

}  // namespace tri::ch10
