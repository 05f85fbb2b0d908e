#include "chapters/11_your_rasterizer/scorecard.hpp"

#include <algorithm>
#include <sstream>

#include "chapters/11_your_rasterizer/failure_diagram.hpp"
#include "common/output_files.hpp"
#include "common/printable_text.hpp"

namespace tri::conformance {
namespace {

std::string quoted_csv(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

// A table cell: one printable line without the column separator.
std::string cell(const std::string& text) {
  std::string out;
  for (const char c : printable_text(text)) {
    if (c == '|') out += '\\';
    out += c;
  }
  return out;
}

}  // namespace

bool Scorecard::all_passed() const noexcept {
  return std::all_of(results.begin(), results.end(), [](const TestResult& r) { return r.passed; });
}

std::string Scorecard::failed_tests() const {
  std::string names;
  for (const TestResult& r : results) {
    if (!r.passed) names += (names.empty() ? "" : ", ") + r.test;
  }
  return names;
}

std::string scorecard_csv(const Scorecard& scorecard) {
  std::ostringstream csv;
  csv << "test,verdict,missed,extra,doubled,detail\n";
  for (const TestResult& r : scorecard.results) {
    csv << r.test << ',' << (r.passed ? "pass" : "fail") << ',' << r.missed << ',' << r.extra << ','
        << r.doubled << ',' << quoted_csv(printable_text(r.detail)) << '\n';
  }
  return csv.str();
}

std::string diagram_file_name(const TestResult& result) {
  return result.test + ".svg";
}

std::string scorecard_markdown(const Scorecard& scorecard) {
  std::ostringstream md;
  const auto passed = std::count_if(scorecard.results.begin(), scorecard.results.end(),
                                    [](const TestResult& r) { return r.passed; });
  md << "# Conformance of " << cell(scorecard.rasterizer) << "\n\n"
     << "Graded under the " << tie_rule_name(scorecard.rule) << " tie rule: " << passed << " of "
     << scorecard.results.size() << " tests pass.\n\n"
     << "| test | verdict | missed | extra | doubled | detail |\n"
     << "|---|---|---:|---:|---:|---|\n";
  for (const TestResult& r : scorecard.results) {
    const std::string verdict =
        r.passed ? "pass" : (r.smallest_failure ? "[fail](" + diagram_file_name(r) + ")" : "fail");
    md << "| `" << r.test << "` | " << verdict << " | " << r.missed << " | " << r.extra << " | "
       << r.doubled << " | " << cell(r.detail) << " |\n";
  }
  md << "\nWhat each test checks:\n\n";
  for (const TestResult& r : scorecard.results) md << "- `" << r.test << "`: " << r.promise << "\n";
  bool any_diagram = false;
  for (const TestResult& r : scorecard.results) {
    if (r.passed || !r.smallest_failure) continue;
    if (!any_diagram) md << "\n## The smallest failing case of each failed test\n";
    any_diagram = true;
    md << "\n### `" << r.test << "`: " << cell(r.smallest_failure->label) << "\n\n![" << r.test
       << ": the wrong pixels of case " << cell(r.smallest_failure->label) << "]("
       << diagram_file_name(r) << ")\n";
  }
  return md.str();
}

void write_scorecard(const Scorecard& scorecard, const std::filesystem::path& folder) {
  OutputTransaction outputs;
  const std::string markdown = scorecard_markdown(scorecard);
  const std::string csv = scorecard_csv(scorecard);
  for (const TestResult& r : scorecard.results) {
    if (r.passed || !r.smallest_failure) continue;
    const std::string svg =
        failure_diagram_svg(*r.smallest_failure, r.test + ": " + r.smallest_failure->label);
    outputs.stage(folder / diagram_file_name(r), bytes_of_text(svg));
  }
  outputs.stage(folder / "scorecard.csv", bytes_of_text(csv));
  outputs.stage(folder / "scorecard.md", bytes_of_text(markdown));
  outputs.commit();
}

}  // namespace tri::conformance
