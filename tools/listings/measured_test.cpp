#include "tools/listings/measured.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

#include "tools/listings/listings.hpp"
#include "tools/listings/temp_repo.hpp"

using namespace tri::listings;
using tri::listings::testing::any_problem_contains;
using tri::listings::testing::TempRepo;

namespace {

const std::string kSnapshot =
    "# Measurement snapshot of chapter 10's report, quick setting\n"
    "# machine: test machine\n"
    "# commit: 0123456789ab\n"
    "key,value\n"
    "area_cells.cost_vs_fastest,2.96831\n"
    "fast.large_integer.median_s,0.002\n"
    "slow.large_integer.median_s,0.0126\n";

constexpr const char* kSnapshotFile = "docs/measurements/report_quick.csv";

std::string marker(const std::string& key_and_format, const std::string& value) {
  return "<!-- measured: " + std::string(kSnapshotFile) + " " + key_and_format + " -->" + value +
         "<!-- /measured -->";
}

// A repository with the snapshot and a README whose one line holds `line`.
void write_repo(const TempRepo& repo, const std::string& line) {
  repo.write(kSnapshotFile, kSnapshot);
  repo.write("ch/README.md", "# Cost\n\nThe area took " + line + " the time.\n");
}

}  // namespace

TEST_CASE("A snapshot's numbers are its KEY,VALUE lines after the header", "[listings]") {
  const auto numbers = parse_snapshot(kSnapshot);
  REQUIRE(numbers);
  CHECK(numbers->size() == 3);
  CHECK(numbers->at("area_cells.cost_vs_fastest") == 2.96831);
  CHECK_FALSE(parse_snapshot("area_cells.cost_vs_fastest,2.9\n"));  // no key,value line
  CHECK_FALSE(parse_snapshot("key,value\narea_cells,fast\n"));      // not a number
}

TEST_CASE("A format gives significant digits or decimals, then its suffix", "[listings]") {
  CHECK(format_measured(2.96831, "s3×") == "2.97×");
  CHECK(format_measured(29.345, "s3×") == "29.3×");
  CHECK(format_measured(0.0123456, "s2") == "0.012");
  CHECK(format_measured(12345.4, "s3") == "12345");  // digits left of the point are kept
  CHECK(format_measured(12.345, "f1%") == "12.3%");
  CHECK(format_measured(2.96831, "") == "2.97");  // three significant digits by default
  CHECK_FALSE(format_measured(1.0, "x3"));
  CHECK_FALSE(format_measured(1.0, "s"));
  CHECK_FALSE(format_measured(1.0, "s0"));
}

TEST_CASE("Update fills a measured marker from its snapshot, and the check then passes",
          "[listings]") {
  TempRepo repo;
  write_repo(repo, marker("area_cells.cost_vs_fastest s3×", ""));
  const auto updated = update_listings(repo.root());
  CHECK(updated.problems.empty());
  CHECK(updated.measured == 1);
  CHECK(repo.read("ch/README.md") == "# Cost\n\nThe area took " +
                                         marker("area_cells.cost_vs_fastest s3×", "2.97×") +
                                         " the time.\n");
  const auto checked = check_listings(repo.root());
  CHECK(checked.problems.empty());
  CHECK(checked.measured == 1);
}

TEST_CASE("A ratio marker shows the quotient of two keys of the snapshot", "[listings]") {
  TempRepo repo;
  const std::string key = "ratio:slow.large_integer.median_s/fast.large_integer.median_s f1×";
  write_repo(repo, marker(key, "9.9×") + " and " + marker("fast.large_integer.median_s", "1"));
  CHECK(update_listings(repo.root()).problems.empty());
  CHECK(repo.read("ch/README.md")
            .find(marker(key, "6.3×") + " and " +
                  marker("fast.large_integer.median_s", "0.00200")) != std::string::npos);
}

TEST_CASE("A number in the text that differs from its snapshot fails the check", "[listings]") {
  TempRepo repo;
  write_repo(repo, marker("area_cells.cost_vs_fastest s3×", "2.98×"));
  const auto report = check_listings(repo.root());
  REQUIRE(report.problems.size() == 1);
  CHECK(report.problems.front().line == 3);
  CHECK(report.problems.front().refreshable);
  CHECK(any_problem_contains(report, "measured value 2.98× differs from 2.97×"));
  CHECK(any_problem_contains(report, std::string(kMeasuredRefreshCommand)));
  CHECK(repo.read("ch/README.md").find("2.98×") != std::string::npos);  // check writes nothing
}

TEST_CASE("A measured marker naming a missing key fails, and update cannot fix it", "[listings]") {
  TempRepo repo;
  write_repo(repo, marker("area_cells.no_such_metric s3×", "2.97×") + " and " +
                       marker("ratio:area_cells.cost_vs_fastest/none s3", "1"));
  for (const auto& report : {check_listings(repo.root()), update_listings(repo.root())}) {
    CHECK(report.problems.size() == 2);
    CHECK(any_problem_contains(report, "key 'area_cells.no_such_metric' is not in"));
    CHECK(any_problem_contains(report, "key 'none' is not in"));
  }
  CHECK(repo.read("ch/README.md").find("-->2.97×<!--") != std::string::npos);
}

TEST_CASE("A measured marker naming a missing snapshot fails, and update cannot fix it",
          "[listings]") {
  TempRepo repo;
  repo.write("ch/README.md",
             "<!-- measured: docs/measurements/none.csv a.b -->1<!-- /measured -->\n");
  for (const auto& report : {check_listings(repo.root()), update_listings(repo.root())}) {
    REQUIRE(report.problems.size() == 1);
    CHECK(any_problem_contains(report, "names docs/measurements/none.csv, which is missing"));
  }
}

TEST_CASE("A malformed measured marker or format fails the check", "[listings]") {
  TempRepo repo;
  write_repo(repo, "<!-- measured: " + std::string(kSnapshotFile) + " -->1<!-- /measured --> " +
                       marker("area_cells.cost_vs_fastest q3", "1") +
                       " <!-- measured: a b -->1 unclosed");
  const auto report = check_listings(repo.root());
  CHECK(report.problems.size() == 3);
  CHECK(any_problem_contains(report, "format 'q3' is not sN or fN"));
  CHECK(any_problem_contains(report, "on one line"));
}

TEST_CASE("A measured marker in a fenced block or inline code is text, not a marker",
          "[listings]") {
  TempRepo repo;
  repo.write("README.md",
             "Write `<!-- measured: none.csv a.b -->1<!-- /measured -->` or:\n\n```md\n"
             "<!-- measured: none.csv a.b -->1<!-- /measured -->\n```\n");
  const auto report = check_listings(repo.root());
  CHECK(report.problems.empty());
  CHECK(report.measured == 0);
}
