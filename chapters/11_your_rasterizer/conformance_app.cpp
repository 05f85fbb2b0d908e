#include "chapters/11_your_rasterizer/conformance_app.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "chapters/11_your_rasterizer/command_rasterizer.hpp"
#include "chapters/11_your_rasterizer/named_tests.hpp"
#include "common/cli.hpp"
#include "common/output_files.hpp"
#include "common/printable_text.hpp"
#include "measure/registry.hpp"

namespace tri::conformance {
namespace {

const CommandLine& command_line() {
  static const CommandLine line(
      "conformance",
      "Grades a rasterizer on named tests against chapter 07's exact oracle: hard cases, random "
      "triangles on the 1/256 grid, watertight meshes, the tie rule, vertex order, translation, "
      "range (±32768 and ±2^30), degenerate and bad input, determinism. Prints one row per test "
      "and writes the scorecard (Markdown, CSV, a pixel diagram per failure) into --out. A failed "
      "test is exit status 1.",
      {{"algo", "NAME", "a registered algorithm (raster --list); not one of rule area"},
       {"command", "'PROGRAM ... {scene} {counts}'",
        "a program run once per case without a shell: it reads the scene file {scene} and writes "
        "the write counts to {counts} as a binary PGM, top row first, as raster --counts does"},
       {"rule", "top-left|bottom-left|any",
        "the tie rule graded (default: the algorithm's own exact rule, else top-left)"},
       {"out", "DIR", "where scorecard.md, scorecard.csv and the failures' diagrams go"},
       {"time-limit", "S", "seconds one test may take, 1 to 3600 (default 20)"}});
  return line;
}

// One row of the printed table: the scorecard's columns, aligned.
std::string row(const std::string& test, const std::string& verdict, const std::string& missed,
                const std::string& extra, const std::string& doubled, const std::string& detail) {
  const auto padded = [](std::string text, std::size_t width, bool right) {
    const std::string pad(text.size() < width ? width - text.size() : 0, ' ');
    return right ? pad + text : text + pad;
  };
  return padded(test, 18, false) + " " + padded(verdict, 7, false) + padded(missed, 8, true) +
         padded(extra, 8, true) + padded(doubled, 8, true) + "  " + printable_text(detail) + "\n";
}

}  // namespace

int run_suite(const GradedRasterizer& rasterizer, TieRule rule,
              std::chrono::milliseconds time_limit,
              const std::optional<std::filesystem::path>& folder, std::ostream& out,
              std::ostream& err) {
  const auto tests = named_tests();
  Scorecard scorecard{rasterizer.name, rule, grade_all(tests, rasterizer, rule, time_limit)};
  if (folder) write_scorecard(scorecard, *folder);
  out << row("test", "verdict", "missed", "extra", "doubled", "detail");
  for (const TestResult& r : scorecard.results) {
    out << row(r.test, r.passed ? "pass" : "fail", std::to_string(r.missed),
               std::to_string(r.extra), std::to_string(r.doubled), r.detail);
  }
  if (scorecard.all_passed()) return exit_success;
  const auto failed = std::count_if(scorecard.results.begin(), scorecard.results.end(),
                                    [](const TestResult& r) { return !r.passed; });
  err << "conformance: " << failed << " of " << scorecard.results.size()
      << " tests failed: " << scorecard.failed_tests() << "\n";
  return exit_failure;
}

int run_conformance(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
  const auto drawables = registered_drawables();
  return run_conformance(drawables, argc, argv, out, err);
}

int run_conformance(std::span<const Drawable> drawables, int argc, const char* const* argv,
                    std::ostream& out, std::ostream& err) {
  return run_command_line(command_line(), argc, argv, out, err, [&](const CliArguments& args) {
    if (args.has("algo") == args.has("command")) {
      throw UsageError("give exactly one of --algo NAME and --command 'PROGRAM ...'");
    }
    std::optional<TieRule> rule;
    if (const auto name = args.value("rule")) {
      rule = parse_tie_rule(*name);
      if (!rule) {
        throw UsageError("--rule must be top-left, bottom-left or any, not " +
                         printable_excerpt(*name));
      }
    }
    const auto seconds = args.integer("time-limit", 1, 3600).value_or(20);
    std::optional<std::filesystem::path> folder;
    if (const auto value = args.value("out")) {
      folder = *value;
      check_output_folder(*folder);
    }
    if (const auto command = args.value("command")) {
      return run_suite(graded_command(*command), rule.value_or(TieRule::top_left),
                       std::chrono::seconds(seconds), folder, out, err);
    }
    const std::string name = *args.value("algo");
    const Drawable* drawable = find_named(drawables, name);
    if (drawable == nullptr) {
      std::string names;
      for (const Drawable& d : drawables)
        names += (names.empty() ? "" : ", ") + std::string(d.name);
      throw UsageError("unknown algorithm " + printable_excerpt(name) + " (one of: " + names + ")");
    }
    if (drawable->colours == nullptr || !drawable->writes(Output::counts)) {
      throw UsageError(
          std::string(drawable->name) + " draws fractions of pixels (rule " +
          std::string(rule_name(drawable->rule)) +
          "): anti-aliasing is outside the suite, which grades which pixels are drawn");
    }
    return run_suite(graded_algorithm(*drawable->colours),
                     rule.value_or(declared_tie_rule(drawable->rule)),
                     std::chrono::seconds(seconds), folder, out, err);
  });
}

}  // namespace tri::conformance
