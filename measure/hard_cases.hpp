/// @file
/// The shared hard cases of docs/DESIGN.md section 7: small scenes, each with a name and the reason
/// it is hard, that every registered algorithm is run against.
#pragma once

#include <string>
#include <vector>

#include "common/scene.hpp"
#include "common/triangle_algorithm.hpp"
#include "measure/error_metrics.hpp"

namespace tri::hard_cases {

/// One hard case.
struct HardCase {
  std::string name;               ///< stable identifier, e.g. "horizontal_top_edge"
  std::string reason;             ///< what it tests, in one line
  Scene scene;                    ///< a 32x32 canvas and its triangles
  bool expect_rejection = false;  ///< NaN/inf input: every triangle must be refused
};

/// Every hard case, in a fixed order.
std::vector<HardCase> all_cases();

/// The outcome of one algorithm on one case.
struct Outcome {
  std::string algorithm;
  std::string rule;
  std::string case_name;
  ErrorReport error;
  /// Safe: nothing written outside the canvas, and NaN/inf refused where expected.
  bool safe = false;
};

/// Runs one algorithm on one case.
Outcome run_case(const TriangleAlgorithm& algorithm, const HardCase& hard_case);

/// The matrix of every registered algorithm on every case.
std::vector<Outcome> run_all(const std::vector<TriangleAlgorithm>& algorithms);

/// One CSV line per outcome with a header: the format of tests/hard_cases_expected.csv.
std::string to_csv(const std::vector<Outcome>& outcomes);

}  // namespace tri::hard_cases
