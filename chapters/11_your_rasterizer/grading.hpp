/// @file
/// Grading: every case of a named test drawn by the rasterizer under test and compared with what
/// the tie rule expects (or with an earlier case), summed into one verdict per test.
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "chapters/11_your_rasterizer/graded_rasterizer.hpp"
#include "chapters/11_your_rasterizer/named_tests.hpp"
#include "chapters/11_your_rasterizer/tie_rule.hpp"
#include "common/scene.hpp"

namespace tri::conformance {

/// The wrong pixels of one failing case, for its diagram.
struct WrongCase {
  std::string label;
  Scene scene;
  std::vector<std::uint32_t> expected;  ///< the counts the case should have (the lower bound)
  std::vector<glm::ivec2> missed;       ///< drawn less often than expected
  std::vector<glm::ivec2> extra;        ///< drawn more often than allowed
  std::vector<glm::ivec2> doubled;      ///< among extra: drawn more than once
};

/// One row of the scorecard.
struct TestResult {
  std::string test;
  std::string promise;
  bool passed = false;
  std::uint64_t missed = 0;   ///< sum over the cases of writes left out
  std::uint64_t extra = 0;    ///< sum over the cases of writes not allowed
  std::uint64_t doubled = 0;  ///< pixels written more than once where at most once is allowed
  std::string detail;         ///< one line: what failed and why, or how many cases passed
  std::optional<WrongCase> smallest_failure;  ///< the failing case with fewest triangles
};

/// How long one test may take before it fails; the default of --time-limit.
inline constexpr std::chrono::seconds default_time_limit{20};

/// Draws every case of the test with the rasterizer and judges it under the rule. A crash, a hang
/// past the time limit, an unreadable answer or a refused good scene fails the test with the
/// reason; refusing a bad-input scene passes.
TestResult grade(const NamedTest& test, const GradedRasterizer& rasterizer, TieRule rule,
                 std::chrono::milliseconds time_limit = default_time_limit);

/// grade() for every test, in order.
std::vector<TestResult> grade_all(std::span<const NamedTest> tests,
                                  const GradedRasterizer& rasterizer, TieRule rule,
                                  std::chrono::milliseconds time_limit = default_time_limit);

}  // namespace tri::conformance
