#include <catch2/catch.hpp>

#include <filesystem>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/scratch_folder.hpp"
#include "chapters/11_your_rasterizer/command_rasterizer.hpp"
#include "chapters/11_your_rasterizer/conformance_app.hpp"
#include "chapters/11_your_rasterizer/grading.hpp"
#include "chapters/11_your_rasterizer/named_tests.hpp"

using namespace tri;
using namespace tri::conformance;

namespace {

// The external rasterizer with one planted fault ("" for none), as --command runs it.
std::string command_with(const std::string& fault) {
  std::string command = std::string("'") + EXTERNAL_RASTERIZER + "'";
  if (!fault.empty()) command += " --fault " + fault;
  return command + " {scene} {counts}";
}

std::vector<TestResult> graded(const std::string& fault, TieRule rule,
                               std::chrono::milliseconds limit = default_time_limit) {
  return grade_all(named_tests(), graded_command(command_with(fault)), rule, limit);
}

std::set<std::string> failed(const std::vector<TestResult>& results) {
  std::set<std::string> names;
  for (const TestResult& r : results) {
    if (!r.passed) names.insert(r.test);
  }
  return names;
}

const TestResult& result_of(const std::vector<TestResult>& results, const std::string& test) {
  for (const TestResult& r : results) {
    if (r.test == test) return r;
  }
  FAIL("no test " << test);
  return results.front();
}

}  // namespace

TEST_CASE("An external rasterizer with the top-left rule passes every test through --command",
          "[conformance]") {
  CHECK(failed(graded("", TieRule::top_left)).empty());
  CHECK(failed(graded("", TieRule::any)).empty());
}

TEST_CASE("The same rasterizer with the bottom-left rule passes under --rule bottom-left only",
          "[conformance]") {
  CHECK(failed(graded("bottom_left", TieRule::bottom_left)).empty());
  CHECK(failed(graded("bottom_left", TieRule::top_left)) ==
        std::set<std::string>{"hard_cases", "tie_rule"});
}

TEST_CASE("Each planted fault fails the tests that guard its promise", "[conformance]") {
  // Pinned: a change of any verdict fails here.
  // Every centre on an edge covered: ties alone are some rule's, shared edges are drawn twice.
  const std::set<std::string> inclusive{"hard_cases", "tie_rule", "watertight_meshes"};
  CHECK(failed(graded("inclusive", TieRule::top_left)) == inclusive);
  CHECK(failed(graded("inclusive", TieRule::any)) == inclusive);
  CHECK(failed(graded("bottom_right", TieRule::top_left)) ==
        std::set<std::string>{"hard_cases", "tie_rule"});
  CHECK(failed(graded("snap4", TieRule::top_left)) ==
        std::set<std::string>{"hard_cases", "random_triangles", "watertight_meshes", "tie_rule",
                              "range_32768", "range_2_30"});
  CHECK(failed(graded("float_edges", TieRule::top_left)) ==
        std::set<std::string>{"hard_cases", "range_32768", "range_2_30"});
}

TEST_CASE("A crash on NaN fails bad_input only, and says it crashed", "[conformance]") {
  const auto results = graded("crash_on_nan", TieRule::top_left);
  CHECK(failed(results) == std::set<std::string>{"bad_input"});
  CHECK_THAT(result_of(results, "bad_input").detail,
             Catch::Matches("case \"nan_vertex\": crashed: signal 6 .*"));
}

TEST_CASE(
    "Refusing a NaN scene with a message passes, and a hang fails that test at its time limit",
    "[conformance]") {
  CHECK(failed(graded("refuse_nan", TieRule::top_left)).empty());
  // A short limit for the test that hangs, the default for the others (a busy machine needs it).
  const GradedRasterizer hanging = graded_command(command_with("hang_on_nan"));
  std::vector<TestResult> hung;
  for (const NamedTest& test : named_tests()) {
    const bool bad_input = test.name == "bad_input";
    hung.push_back(grade(test, hanging, TieRule::top_left,
                         bad_input ? std::chrono::milliseconds(500) : default_time_limit));
  }
  CHECK(failed(hung) == std::set<std::string>{"bad_input"});
  CHECK(result_of(hung, "bad_input").detail.find("did not finish in time and was killed") !=
        std::string::npos);
}

TEST_CASE("An unreadable counts file, or a program that cannot start, fails each test with why",
          "[conformance]") {
  for (const TestResult& r : graded("unreadable", TieRule::top_left)) {
    INFO(r.test);
    CHECK_FALSE(r.passed);
    CHECK(r.detail.find("unreadable counts: not a binary PGM") != std::string::npos);
  }
  const auto missing = grade_all(
      named_tests(), graded_command("/nonexistent/rasterizer {scene} {counts}"), TieRule::top_left);
  for (const TestResult& r : missing) {
    INFO(r.test);
    CHECK_FALSE(r.passed);
    CHECK(r.detail.find("cannot start /nonexistent/rasterizer") != std::string::npos);
  }
}

TEST_CASE("command_words splits at spaces, keeps quoted spaces and runs no shell syntax",
          "[conformance]") {
  CHECK(command_words("python3 'my fill.py' --x \"a b\" {scene} {counts}") ==
        std::vector<std::string>{"python3", "my fill.py", "--x", "a b", "{scene}", "{counts}"});
  CHECK(command_words("prog --in={scene} $HOME;rm * {counts}") ==
        std::vector<std::string>{"prog", "--in={scene}", "$HOME;rm", "*", "{counts}"});
}

TEST_CASE("conformance --command writes the scorecard and exits 1 naming the failed tests",
          "[conformance]") {
  tri::testing::ScratchFolder folder("conformance_command");
  const std::string command = command_with("crash_on_nan");
  std::vector<const char*> argv{"conformance", "--command", command.c_str(), "--out",
                                folder.path().c_str()};
  std::ostringstream out, err;
  CHECK(run_conformance(static_cast<int>(argv.size()), argv.data(), out, err) == 1);
  CHECK(err.str() == "conformance: 1 of 11 tests failed: bad_input\n");
  // A crash has no pixels to show: no diagram.
  CHECK(tri::testing::names_in(folder.path()) ==
        std::vector<std::string>{"scorecard.csv", "scorecard.md"});
  CHECK(tri::testing::read_text(folder / "scorecard.csv").find("\nbad_input,fail,0,0,0,\"case ") !=
        std::string::npos);
}
