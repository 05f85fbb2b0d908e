#include "tools/listings/listings.hpp"
#include "tools/listings/temp_repo.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

// The tests sit beside their helpers (temp_repo.hpp), in the tool's namespace.
namespace tri::listings::testing {

namespace {

const std::string kSource =
    "#include \"walk.hpp\"\n"
    "\n"
    "int walk(int n) {\n"
    "  int sum = 0;\n"
    "  // [listing walk_loop]\n"
    "  for (int i = 0; i < n; ++i) {\n"
    "    sum += i;\n"
    "  }\n"
    "  // [/listing]\n"
    "  return sum;\n"
    "}\n";

const std::string kListing =
    "<!-- listing: ch/walk.cpp walk_loop -->\n"
    "```cpp\n"
    "for (int i = 0; i < n; ++i) {\n"
    "  sum += i;\n"
    "}\n"
    "```\n";

const std::string kReadme = "# Walk\n\nThe loop adds every step:\n\n" + kListing + "\nDone.\n";

// The listing comment is on line 5 of kReadme.
constexpr int kListingLine = 5;

// text with its first `from` replaced by `to`.
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  return text.replace(text.find(from), from.size(), to);
}

}  // namespace

TEST_CASE("A README whose listing equals its marked region passes the check", "[listings]") {
  TempRepo repo;
  repo.write("ch/walk.cpp", kSource);
  repo.write("ch/README.md", kReadme);
  const auto report = check_listings(repo.root());
  CHECK(report.problems.empty());
  CHECK(report.listings == 1);
}

TEST_CASE("A listing shows the region without its marker lines and common indentation",
          "[listings]") {
  const auto markers = parse_markers(kSource, "walk.cpp");
  REQUIRE(markers.problems.empty());
  REQUIRE(markers.regions.size() == 1);
  CHECK(markers.regions[0].name == "walk_loop");
  CHECK(markers.regions[0].first_line == 5);
  CHECK(markers.regions[0].text == "for (int i = 0; i < n; ++i) {\n  sum += i;\n}\n");
}

TEST_CASE(
    "A README whose listing differs from its region fails, naming the README line, the source, the "
    "region and the refresh command",
    "[listings]") {
  TempRepo repo;
  repo.write("ch/walk.cpp", kSource);
  std::string readme = kReadme;
  readme.replace(readme.find("sum += i;"), 9, "sum += 2 * i;");
  repo.write("ch/README.md", readme);
  const auto report = check_listings(repo.root());
  REQUIRE(report.problems.size() == 1);
  const auto& problem = report.problems[0];
  CHECK(problem.file == "ch/README.md");
  CHECK(problem.line == kListingLine);
  const auto message = format(problem);
  CHECK(message.starts_with("ch/README.md:5: "));
  CHECK(message.find("ch/walk.cpp") != std::string::npos);
  CHECK(message.find("walk_loop") != std::string::npos);
  CHECK(message.find(std::string(kRefreshCommand)) != std::string::npos);
}

TEST_CASE("Changing a marked region without the README makes the check fail", "[listings]") {
  TempRepo repo;
  repo.write("ch/walk.cpp", kSource);
  repo.write("ch/README.md", kReadme);
  REQUIRE(check_listings(repo.root()).problems.empty());

  repo.write("ch/walk.cpp", replaced(kSource, "++i", "i += 2"));
  const auto report = check_listings(repo.root());
  REQUIRE(report.problems.size() == 1);
  CHECK(report.problems[0].line == kListingLine);
  CHECK(any_problem_contains(report, "differs from ch/walk.cpp region 'walk_loop'"));
}

TEST_CASE("Update rewrites a listing from its changed region, so the check passes again",
          "[listings]") {
  TempRepo repo;
  repo.write("ch/walk.cpp", replaced(kSource, "++i", "i += 2"));
  repo.write("ch/README.md", kReadme);
  REQUIRE_FALSE(check_listings(repo.root()).problems.empty());

  const auto report = update_listings(repo.root());
  CHECK(report.problems.empty());
  CHECK(report.rewritten == std::vector<std::string>{"ch/README.md"});
  CHECK(check_listings(repo.root()).problems.empty());

  CHECK(repo.read("ch/README.md") == replaced(kReadme, "++i", "i += 2"));
}

TEST_CASE("Update adds the block after a listing comment that has none, and nothing else",
          "[listings]") {
  TempRepo repo;
  repo.write("ch/walk.cpp", kSource);
  repo.write("ch/README.md",
             "# Walk\n\nThe loop adds every step:\n\n<!-- listing: ch/walk.cpp walk_loop -->\n"
             "\nDone.\n");
  const auto before = check_listings(repo.root());
  REQUIRE(before.problems.size() == 1);
  CHECK(any_problem_contains(before, "is not followed by a ```cpp block"));

  CHECK(update_listings(repo.root()).problems.empty());
  CHECK(repo.read("ch/README.md") == kReadme);
  // A second update changes nothing.
  CHECK(update_listings(repo.root()).rewritten.empty());
}

TEST_CASE("A listing that names a missing file fails the check, and update cannot fix it",
          "[listings]") {
  TempRepo repo;
  repo.write("ch/README.md", kReadme);
  const auto report = check_listings(repo.root());
  REQUIRE(report.problems.size() == 1);
  CHECK(report.problems[0].line == kListingLine);
  CHECK(any_problem_contains(report, "ch/walk.cpp, which does not exist"));
  CHECK(update_listings(repo.root()).problems.size() == 1);
  CHECK(repo.read("ch/README.md") == kReadme);
}

TEST_CASE("A listing that names a missing region fails the check, and update cannot fix it",
          "[listings]") {
  TempRepo repo;
  repo.write("ch/walk.cpp", replaced(kSource, "walk_loop", "other_loop"));
  repo.write("ch/README.md", kReadme);
  const auto report = check_listings(repo.root());
  REQUIRE(report.problems.size() == 1);
  CHECK(report.problems[0].file == "ch/README.md");
  CHECK(any_problem_contains(report, "region 'walk_loop', which ch/walk.cpp does not mark"));
  CHECK(update_listings(repo.root()).problems.size() == 1);
  CHECK(repo.read("ch/README.md") == kReadme);
}

TEST_CASE("A malformed listing comment fails the check", "[listings]") {
  TempRepo repo;
  repo.write("ch/walk.cpp", kSource);
  repo.write("ch/README.md", "<!-- listing: ch/walk.cpp -->\n```cpp\n```\n");
  CHECK(any_problem_contains(check_listings(repo.root()), "malformed listing comment"));
  repo.write("ch/README.md", "<!-- listing: ../walk.cpp walk_loop -->\n```cpp\n```\n");
  CHECK(any_problem_contains(check_listings(repo.root()), "malformed listing comment"));
}

TEST_CASE("A region that is never closed fails the check, even when no README shows it",
          "[listings]") {
  TempRepo repo;
  repo.write("ch/walk.cpp", replaced(kSource, "  // [/listing]\n", ""));
  const auto report = check_listings(repo.root());
  REQUIRE(report.problems.size() == 1);
  CHECK(format(report.problems[0]) ==
        "ch/walk.cpp:5: region 'walk_loop' is never closed by // [/listing]");
}

TEST_CASE("A closing marker with no open region fails the check", "[listings]") {
  const auto markers = parse_markers("int a;\n// [/listing]\n", "a.cpp");
  REQUIRE(markers.problems.size() == 1);
  CHECK(markers.problems[0].line == 2);
  CHECK(markers.problems[0].message.find("closes no region") != std::string::npos);
}

TEST_CASE("A region opened inside another fails the check: regions may not nest or overlap",
          "[listings]") {
  const auto markers = parse_markers(
      "// [listing outer]\nint a;\n// [listing inner]\nint b;\n// [/listing]\n// [/listing]\n",
      "a.cpp");
  REQUIRE_FALSE(markers.problems.empty());
  CHECK(markers.problems[0].line == 3);
  CHECK(markers.problems[0].message.find("may not nest") != std::string::npos);
}

TEST_CASE("A region name used twice in one file, an empty region and a malformed marker fail",
          "[listings]") {
  const auto twice = parse_markers(
      "// [listing a]\nint a;\n// [/listing]\n// [listing a]\nint b;\n// [/listing]\n", "a.cpp");
  REQUIRE(twice.problems.size() == 1);
  CHECK(twice.problems[0].message.find("marked twice") != std::string::npos);

  const auto empty = parse_markers("// [listing a]\n// [/listing]\n", "a.cpp");
  REQUIRE(empty.problems.size() == 1);
  CHECK(empty.problems[0].message.find("is empty") != std::string::npos);

  const auto malformed = parse_markers("// [listing a b]\nint a;\n// [/listing]\n", "a.cpp");
  CHECK_FALSE(malformed.problems.empty());
  CHECK(malformed.problems[0].message.find("malformed marker") != std::string::npos);
}

TEST_CASE("A listing comment inside a fenced example is text, not a listing", "[listings]") {
  TempRepo repo;
  repo.write("README.md", "Write:\n\n```md\n<!-- listing: ch/none.cpp none -->\n```\n");
  const auto report = check_listings(repo.root());
  CHECK(report.problems.empty());
  CHECK(report.listings == 0);
}

TEST_CASE("Build folders and hidden folders are not searched", "[listings]") {
  TempRepo repo;
  repo.write("build/release/README.md", "<!-- listing: missing.cpp none -->\n");
  repo.write(".git/x.cpp", "// [listing open_forever]\n");
  CHECK(check_listings(repo.root()).problems.empty());
}

}  // namespace tri::listings::testing
