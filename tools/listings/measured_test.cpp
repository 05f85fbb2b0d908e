#include "tools/listings/measured.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

#include "tools/listings/listings.hpp"
#include "tools/listings/temp_repo.hpp"

// The tests sit beside their helpers (temp_repo.hpp), in the tool's namespace.
namespace tri::listings::testing {

namespace {

const std::string kSnapshot =
    "# Measurement snapshot of chapter 10's report, quick setting\n"
    "# machine: test machine\n"
    "# commit: 0123456789ab\n"
    "# peers: pixman 0.42.2, cairo 1.16.0\n"
    "key,value\n"
    "fast.chapter,08_fast_exact\n"
    "fast.threaded,0\n"
    "fast.large_mpix_per_s,4155.4\n"
    "fast.tiny_tris_per_s,15400000\n"
    "fast.mesh_tris_per_s,907000\n"
    "fast.mpix_per_s,17.44\n"
    "fast.error_rate,0\n"
    "peer.chapter,external\n"
    "peer.threaded,1\n"
    "peer.large_mpix_per_s,99.96\n"
    "peer.tiny_tris_per_s,950\n"
    "peer.mesh_tris_per_s,12345\n"
    "peer.mpix_per_s,354.4\n"
    "peer.error_rate,5.41e-06\n"
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

// Update writes `file` as `expected` from the snapshot, with one marker, and the check then passes.
void check_update_fills(const TempRepo& repo, const std::string& file,
                        const std::string& expected) {
  const auto updated = update_listings(repo.root());
  CHECK(updated.problems.empty());
  CHECK(updated.measured == 1);
  CHECK(repo.read(file) == expected);
  const auto checked = check_listings(repo.root());
  CHECK(checked.problems.empty());
  CHECK(checked.measured == 1);
}

}  // namespace

TEST_CASE("A format gives significant digits or decimals, then its suffix", "[listings]") {
  CHECK(format_measured(2.96831, "s3×") == "2.97×");
  CHECK(format_measured(29.345, "s3×") == "29.3×");
  CHECK(format_measured(0.0123456, "s2") == "0.012");
  CHECK(format_measured(12345.4, "s3") == "12345");  // digits left of the point are kept
  CHECK(format_measured(12.345, "f1%") == "12.3%");
  CHECK(format_measured(0.002, "s3") == "0.002");  // as the report writes it: no trailing zeros
  CHECK(format_measured(6.0, "f1") == "6");
  CHECK(format_measured(2.96831, "") == "2.97");  // three significant digits by default
  CHECK_FALSE(format_measured(1.0, "x3"));
  CHECK_FALSE(format_measured(1.0, "s"));
  CHECK_FALSE(format_measured(1.0, "s0"));
}

TEST_CASE("Update fills a measured marker from its snapshot, and the check then passes",
          "[listings]") {
  TempRepo repo;
  write_repo(repo, marker("area_cells.cost_vs_fastest s3×", ""));
  check_update_fills(repo, "ch/README.md",
                     "# Cost\n\nThe area took " +
                         marker("area_cells.cost_vs_fastest s3×", "2.97×") + " the time.\n");
}

TEST_CASE("A ratio marker shows the quotient of two keys of the snapshot", "[listings]") {
  TempRepo repo;
  const std::string key = "ratio:slow.large_integer.median_s/fast.large_integer.median_s f1×";
  write_repo(repo, marker(key, "9.9×") + " and " + marker("fast.large_integer.median_s", "1"));
  CHECK(update_listings(repo.root()).problems.empty());
  CHECK(repo.read("ch/README.md")
            .find(marker(key, "6.3×") + " and " + marker("fast.large_integer.median_s", "0.002")) !=
        std::string::npos);
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

TEST_CASE("A header marker shows the snapshot's header text, and a text key its text",
          "[listings]") {
  TempRepo repo;
  write_repo(repo, marker("header:peers", "") + " " + marker("peer.chapter", "") + " " +
                       marker("header:commit s3", "1") + " " + marker("header:none", "1") + " " +
                       marker("ratio:peer.chapter/fast.mpix_per_s", "1"));
  const auto report = update_listings(repo.root());
  CHECK(report.problems.size() == 3);
  CHECK(any_problem_contains(report, "header 'commit' takes no format"));
  CHECK(any_problem_contains(report, "header 'none' is not in"));
  CHECK(any_problem_contains(
      report, "key 'peer.chapter' of " + std::string(kSnapshotFile) + " is text, not a number"));
  CHECK(repo.read("ch/README.md")
            .find(marker("header:peers", "pixman 0.42.2, cairo 1.16.0") + " " +
                  marker("peer.chapter", "external")) != std::string::npos);
}

namespace {

const std::string kTableOpen =
    "<!-- measured-table: " + std::string(kSnapshotFile) + " summary -->";

const std::string kSummaryTable =
    "| algorithm | chapter | Mpix/s large | tris/s tiny | tris/s mesh | Mpix/s all | error rate |\n"
    "|---|---|--:|--:|--:|--:|--:|\n"
    "| `fast` | 08_fast_exact | 4155 | 15.4 M | 907 k | 17.4 | 0 (exact) |\n"
    "| `peer` (threaded) | external | 100 | 950 | 12.3 k | 354 | 5.41e-06 |\n";

std::string table_readme(const std::string& table) {
  return "# Speed\n\n" + kTableOpen + "\n" + table + "<!-- /measured-table -->\n\nAfter.\n";
}

}  // namespace

TEST_CASE("A measured table block is written from its snapshot, one row per algorithm in order",
          "[listings]") {
  TempRepo repo;
  repo.write(kSnapshotFile, kSnapshot);
  repo.write("README.md", table_readme("| old |\n| table |\n| of three lines |\n"));
  check_update_fills(repo, "README.md", table_readme(kSummaryTable));
}

TEST_CASE("One cell of a measured table that differs from its snapshot fails the check",
          "[listings]") {
  TempRepo repo;
  repo.write(kSnapshotFile, kSnapshot);
  std::string table = kSummaryTable;
  table.replace(table.find("| 354 |"), 7, "| 355 |");
  repo.write("README.md", table_readme(table));
  const auto report = check_listings(repo.root());
  REQUIRE(report.problems.size() == 1);
  CHECK(report.problems.front().line == 7);
  CHECK(report.problems.front().refreshable);
  CHECK(any_problem_contains(report, "| 355 | 5.41e-06 |' differs from"));
  CHECK(repo.read("README.md") == table_readme(table));  // check writes nothing
}

TEST_CASE("A measured table that is unclosed, unknown or from a missing snapshot fails",
          "[listings]") {
  TempRepo repo;
  repo.write(kSnapshotFile, kSnapshot);
  repo.write("a/README.md", kTableOpen + "\n| a |\n");
  repo.write("b/README.md", "<!-- measured-table: " + std::string(kSnapshotFile) +
                                " other -->\n<!-- /measured-table -->\n");
  repo.write("c/README.md",
             "<!-- measured-table: none.csv summary -->\n<!-- /measured-table -->\n");
  const auto report = update_listings(repo.root());
  CHECK(report.problems.size() == 3);
  CHECK(any_problem_contains(report, "malformed measured table"));
  CHECK(any_problem_contains(report, "table 'other' is not one the tool writes"));
  CHECK(any_problem_contains(report, "measured table names none.csv, which is missing"));
}

}  // namespace tri::listings::testing
