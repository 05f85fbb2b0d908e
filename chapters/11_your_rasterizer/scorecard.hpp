/// @file
/// The scorecard: one row per named test (verdict, missed, extra and doubled pixels, a detail),
/// written as Markdown and CSV with a pixel diagram of each failure's smallest case.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "chapters/11_your_rasterizer/grading.hpp"
#include "chapters/11_your_rasterizer/tie_rule.hpp"

namespace tri::conformance {

/// Everything a scorecard says.
struct Scorecard {
  std::string rasterizer;  ///< the algorithm's name, or the command
  TieRule rule = TieRule::top_left;
  std::vector<TestResult> results;

  bool all_passed() const noexcept;
  /// The names of the failed tests, comma-separated ("" when all passed).
  std::string failed_tests() const;
};

/// `test,verdict,missed,extra,doubled,detail`, one line per test; verdict is pass or fail, the
/// detail is quoted.
std::string scorecard_csv(const Scorecard& scorecard);

/// A Markdown page: the rasterizer and rule, a table of the tests, the promises, and a link to
/// each failure's diagram.
std::string scorecard_markdown(const Scorecard& scorecard);

/// The file name of a failed test's diagram: "TEST.svg".
std::string diagram_file_name(const TestResult& result);

/// Writes scorecard.md, scorecard.csv and a diagram per failure into folder as one set
/// (common/output_files.hpp): all of them or, on a failure, none.
void write_scorecard(const Scorecard& scorecard, const std::filesystem::path& folder);

}  // namespace tri::conformance
