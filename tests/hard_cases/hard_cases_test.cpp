#include <catch2/catch.hpp>

#include <fstream>
#include <map>
#include <sstream>

#include "hard_cases.hpp"
#include "registry.hpp"

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

TEST_CASE("every hard case has a unique name, a reason and a 32x32 scene") {
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

TEST_CASE("every registered algorithm is safe on every hard case") {
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

TEST_CASE("every top-left algorithm matches the oracle exactly on every hard case") {
  for (const auto& algorithm : tri::registered_algorithms()) {
    if (algorithm.rule != tri::CoverageRule::top_left) continue;
    for (const auto& c : all_cases()) {
      INFO(algorithm.name << " on " << c.name);
      const Outcome outcome = run_case(algorithm, c);
      CHECK(outcome.error.missed == 0);
      CHECK(outcome.error.extra == 0);
      CHECK(outcome.error.gaps == 0);
      CHECK(outcome.error.overdraw == 0);
      CHECK(outcome.error.order_dependent == 0);
    }
  }
}

TEST_CASE("every other algorithm deviates exactly as tests/hard_cases_expected.csv records") {
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

TEST_CASE("the hard-case matrix renders one Markdown row per case") {
  const auto cases = all_cases();
  const auto outcomes = run_all(tri::registered_algorithms());
  const std::string md = to_markdown(outcomes, cases);
  for (const auto& c : cases)
    CHECK(md.find("| `" + c.name + "` | " + c.reason + " |") != std::string::npos);
  CHECK(md.find("| **unsafe** |") == std::string::npos);
}
