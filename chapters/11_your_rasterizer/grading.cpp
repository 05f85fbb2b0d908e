#include "chapters/11_your_rasterizer/grading.hpp"

#include <algorithm>
#include <variant>

#include "common/canvas.hpp"

namespace tri::conformance {
namespace {

using Clock = std::chrono::steady_clock;

std::size_t triangle_count(const Scene& scene) {
  return static_cast<std::size_t>(std::count_if(
      scene.primitives.begin(), scene.primitives.end(),
      [](const ScenePrimitive& p) { return std::holds_alternative<SceneTriangle>(p); }));
}

// The counts of `base` moved by `shift` on a canvas of the same size (0 where nothing moves in).
std::vector<std::uint32_t> shifted(const std::vector<std::uint32_t>& base, int width, int height,
                                   glm::ivec2 shift) {
  std::vector<std::uint32_t> out(base.size(), 0);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const int from_x = x - shift.x, from_y = y - shift.y;
      if (from_x >= 0 && from_x < width && from_y >= 0 && from_y < height) {
        out[pixel_index(x, y, width)] = base[pixel_index(from_x, from_y, width)];
      }
    }
  }
  return out;
}

// The counts compared pixel by pixel with the allowed range [low, high].
WrongCase compare(const TestCase& test_case, const std::vector<std::uint32_t>& counts,
                  const ExpectedCounts& expected) {
  WrongCase wrong{test_case.label, test_case.scene, expected.low, {}, {}, {}};
  const int width = test_case.scene.width;
  for (std::size_t i = 0; i < counts.size(); ++i) {
    const glm::ivec2 pixel(static_cast<int>(i % static_cast<std::size_t>(width)),
                           static_cast<int>(i / static_cast<std::size_t>(width)));
    if (counts[i] < expected.low[i]) wrong.missed.push_back(pixel);
    if (counts[i] > expected.high[i]) {
      wrong.extra.push_back(pixel);
      if (counts[i] > 1) wrong.doubled.push_back(pixel);
    }
  }
  return wrong;
}

std::uint64_t sum_of_differences(const std::vector<std::uint32_t>& a,
                                 const std::vector<std::uint32_t>& b) {
  std::uint64_t sum = 0;
  for (std::size_t i = 0; i < a.size(); ++i) sum += a[i] > b[i] ? a[i] - b[i] : 0;
  return sum;
}

struct Tally {
  TestResult result;
  std::size_t wrong_cases = 0;
  std::size_t graded_cases = 0;
  std::string first_problem;  // a crash, a hang, an unreadable answer: ends the test

  void wrong(WrongCase wrong_case, const std::vector<std::uint32_t>& counts,
             const ExpectedCounts& expected) {
    ++wrong_cases;
    result.missed += sum_of_differences(expected.low, counts);
    result.extra += sum_of_differences(counts, expected.high);
    result.doubled += wrong_case.doubled.size();
    const auto size = [](const WrongCase& c) {
      return std::pair(triangle_count(c.scene),
                       static_cast<long long>(c.scene.width) * c.scene.height);
    };
    if (!result.smallest_failure || size(wrong_case) < size(*result.smallest_failure)) {
      result.smallest_failure = std::move(wrong_case);
    }
  }
};

}  // namespace

TestResult grade(const NamedTest& test, const GradedRasterizer& rasterizer, TieRule rule,
                 std::chrono::milliseconds time_limit) {
  Tally tally;
  tally.result.test = test.name;
  tally.result.promise = test.promise;
  const Deadline deadline = Clock::now() + time_limit;
  std::vector<std::optional<std::vector<std::uint32_t>>> answers(test.cases.size());
  for (std::size_t i = 0; i < test.cases.size() && tally.first_problem.empty(); ++i) {
    const TestCase& test_case = test.cases[i];
    if (test_case.only_threaded && !rasterizer.threaded) continue;
    const Scene& scene = test_case.scene;
    Answer answer = rasterizer.draw(scene, test_case.threads, deadline);
    if (Clock::now() > deadline) {
      tally.first_problem = "case \"" + test_case.label + "\": the test took longer than its " +
                            std::to_string(time_limit.count()) + " ms" +
                            (answer.kind == Answer::Kind::failed ? " (" + answer.reason + ")" : "");
      break;
    }
    if (answer.kind == Answer::Kind::failed) {
      tally.first_problem = "case \"" + test_case.label + "\": " + answer.reason;
      break;
    }
    ++tally.graded_cases;
    if (answer.kind == Answer::Kind::refused) {
      if (!test_case.bad_input) {
        tally.first_problem =
            "case \"" + test_case.label + "\": refused a valid scene: " + answer.reason;
      }
      continue;
    }
    const std::size_t pixels = static_cast<std::size_t>(scene.width) * scene.height;
    if (answer.counts.size() != pixels) {
      tally.first_problem = "case \"" + test_case.label + "\": answered " +
                            std::to_string(answer.counts.size()) + " counts for " +
                            std::to_string(pixels) + " pixels";
      break;
    }
    answers[i] = answer.counts;
    std::optional<ExpectedCounts> expected;
    if (test_case.check == Check::rule) expected = expected_counts(scene, rule);
    if (test_case.check == Check::consistent) expected = expected_counts(scene, TieRule::any);
    if (test_case.same_as && answers[test_case.same_as->base]) {
      auto moved = shifted(*answers[test_case.same_as->base], scene.width, scene.height,
                           test_case.same_as->shift);
      expected = ExpectedCounts{moved, moved};
    }
    if (!expected) continue;
    WrongCase wrong = compare(test_case, answer.counts, *expected);
    if (!wrong.missed.empty() || !wrong.extra.empty()) {
      tally.wrong(std::move(wrong), answer.counts, *expected);
    }
  }
  TestResult& result = tally.result;
  result.passed = tally.first_problem.empty() && tally.wrong_cases == 0;
  if (!tally.first_problem.empty()) {
    result.detail = tally.first_problem;
  } else if (tally.wrong_cases > 0) {
    result.detail = std::to_string(tally.wrong_cases) + " of " +
                    std::to_string(tally.graded_cases) + " cases wrong; smallest: \"" +
                    result.smallest_failure->label + "\"";
  } else {
    result.detail = std::to_string(tally.graded_cases) + " cases right";
  }
  return result;
}

std::vector<TestResult> grade_all(std::span<const NamedTest> tests,
                                  const GradedRasterizer& rasterizer, TieRule rule,
                                  std::chrono::milliseconds time_limit) {
  std::vector<TestResult> results;
  for (const NamedTest& test : tests) results.push_back(grade(test, rasterizer, rule, time_limit));
  return results;
}

}  // namespace tri::conformance
