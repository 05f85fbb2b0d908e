#include <catch2/catch.hpp>

#include <algorithm>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include "measure/hard_cases.hpp"
#include "measure/registry.hpp"
#include "tests/hard_cases/deviation_checks.hpp"
#include "tests/hard_cases/hard_case_diagram.hpp"
#include "tests/hard_cases/hard_case_page.hpp"

using namespace tri::hard_cases;

namespace {

// The expected CSV, keyed by "algorithm,case".
std::map<std::string, std::string> read_expected() {
  std::ifstream in(TUTORIAL_HARD_CASES_EXPECTED);
  REQUIRE(in);
  std::map<std::string, std::string> rows;
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    const auto second_comma = line.find(',', line.find(',') + 1);
    rows[line.substr(0, second_comma)] = line;
  }
  return rows;
}

}  // namespace

TEST_CASE("Every hard case has a unique name, a reason and a 32x32 scene", "[hard_cases]") {
  const auto cases = all_cases();
  CHECK(cases.size() >= 25);
  std::map<std::string, int> names;
  for (const auto& c : cases) {
    CHECK(++names[c.name] == 1);
    CHECK_FALSE(c.reason.empty());
    CHECK(c.scene.width == 32);
    CHECK_FALSE(c.scene.primitives.empty());
  }
}

TEST_CASE("Every registered algorithm is safe on every hard case", "[hard_cases]") {
  // No write outside the canvas, NaN and infinities refused, and (by finishing) no hang.
  for (const auto& algorithm : tri::registered_algorithms()) {
    for (const auto& c : all_cases()) {
      INFO(algorithm.name << " on " << c.name);
      const Outcome outcome = run_case(algorithm, c);
      CHECK(outcome.error.outside_writes == 0);
      CHECK(outcome.safe);
    }
  }
}

TEST_CASE("Every top-left algorithm matches the oracle exactly on every hard case",
          "[hard_cases]") {
  for (const auto& algorithm : tri::registered_algorithms()) {
    if (algorithm.rule != tri::CoverageRule::top_left) continue;
    for (const auto& c : all_cases()) {
      INFO(algorithm.name << " on " << c.name);
      tri::testing::check_no_deviation(run_case(algorithm, c).error);
    }
  }
}

TEST_CASE("Every other algorithm deviates exactly as tests/hard_cases_expected.csv records",
          "[hard_cases]") {
  // A change in any count shows here. After an intended change, regenerate the file with
  //   ./build/release/tests/hard_case_matrix --csv tests/hard_cases_expected.csv
  // and explain the new numbers in the commit.
  const auto expected = read_expected();
  std::size_t compared = 0;
  for (const auto& algorithm : tri::registered_algorithms()) {
    if (algorithm.rule == tri::CoverageRule::top_left) continue;
    const auto outcomes = run_all({algorithm});
    std::istringstream csv(to_csv(outcomes));
    std::string line;
    std::getline(csv, line);  // header
    while (std::getline(csv, line)) {
      const auto key = line.substr(0, line.find(',', line.find(',') + 1));
      INFO("measured: " << line);
      const auto it = expected.find(key);
      REQUIRE(it != expected.end());
      CHECK(it->second == line);
      ++compared;
    }
  }
  CHECK(compared > 0);
}

TEST_CASE("The hard-case page has a matrix row and a section with its reason per case",
          "[hard_cases]") {
  const auto cases = all_cases();
  const auto outcomes = run_all(tri::registered_algorithms());
  const std::string md = to_markdown(outcomes, cases);
  for (const auto& c : cases) {
    INFO(c.name);
    // The row links the section by the anchor GitHub makes of its heading, the case's name.
    CHECK(md.find("| [" + c.name + "](#" + c.name + ") |") != std::string::npos);
    CHECK(md.find("\n### " + c.name + "\n") != std::string::npos);
    CHECK(md.find("**Why it is hard:** " + c.reason + ".") != std::string::npos);
    CHECK(md.find("](" + diagram_name(c) + ".svg)") != std::string::npos);
  }
  CHECK(md.find("unsafe**:") == std::string::npos);
  CHECK(md.find("| **unsafe** |") == std::string::npos);
}

TEST_CASE("The hard-case page spells the result codes out", "[hard_cases]") {
  Outcome o{"a", "inclusive", "c", {}, true};
  o.error.extra = 26;
  o.error.overdraw = 1;
  o.error.order_dependent = 13;
  CHECK(cell(o) == "x26 o1 d13");
  CHECK(in_words(o) ==
        "26 extra pixels, 1 pixel drawn too often, 13 pixels that change with the vertex order");
  o.error = {};
  o.error.missed = 1;
  o.error.gaps = 1;
  CHECK(in_words(o) == "1 missed pixel, 1 gap (a covered pixel never drawn)");
  o.error = {};
  CHECK(in_words(o) == "exact");
  o.error.rejected = 1;
  CHECK(in_words(o) == "refused");
  o.safe = false;
  o.error.outside_writes = 3;
  CHECK(in_words(o) == "**unsafe**: 3 writes outside the canvas");
}

TEST_CASE("A case's diagram draws its triangles over the pixels the oracle covers",
          "[hard_cases]") {
  const auto cases = all_cases();
  const auto find = [&](const std::string& name) {
    return *std::find_if(cases.begin(), cases.end(),
                         [&](const HardCase& c) { return c.name == name; });
  };
  const HardCase right = find("right_triangle_on_centres");
  const std::string svg = diagram_svg(right);
  CHECK(svg.rfind("<svg", 0) == 0);
  CHECK(svg == diagram_svg(right));  // deterministic
  CHECK(svg.find("A (2, 2)") != std::string::npos);
  CHECK(svg.find("centre exactly on an edge") != std::string::npos);
  CHECK_FALSE(reaches_beyond_canvas(right));

  // A vertex 2^30 pixels away: the whole canvas, the edges cut to it, the vertex named below.
  const HardCase far = find("vertices_far_2p30");
  CHECK(reaches_beyond_canvas(far));
  const std::string far_svg = diagram_svg(far);
  CHECK(far_svg.find("Outside the picture: A (-1073741824, 3), B (1073741824, 17)") !=
        std::string::npos);
  // Every SVG coordinate stays within the picture (no line to 2^30 pixels away).
  CHECK_FALSE(std::regex_search(far_svg, std::regex("=\"-?[0-9]{5,}")));

  const HardCase nan = find("nan_vertex");
  CHECK(diagram_svg(nan).find("Not finite, so not drawn") != std::string::npos);
  CHECK(diagram_svg(find("all_vertices_equal")).find("No pixel centre is covered") !=
        std::string::npos);
}
