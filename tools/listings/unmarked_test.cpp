#include "tools/listings/unmarked.hpp"

#include <catch2/catch.hpp>

#include <string>
#include <string_view>
#include <utility>

#include "tools/listings/listings.hpp"
#include "tools/listings/temp_repo.hpp"

// The tests sit beside their helpers (temp_repo.hpp), in the tool's namespace.
namespace tri::listings::testing {

TEST_CASE("Times, rates, ratios and shares of a ceiling look measured", "[listings]") {
  // Each text and the number in it that looks measured.
  const std::pair<std::string_view, std::string_view> examples[] = {
      {"the span walker is 3.2× faster", "3.2×"},
      {"3x faster than the oracle", "3x"},
      {"it fills 1164 Mpix/s on large triangles", "1164 Mpix/s"},
      {"at 15.9 Mtri/s", "15.9 Mtri/s"},
      {"about 6.68 M tris/s on tiny ones", "6.68 M tris/s"},
      {"22.5 tris/s", "22.5 tris/s"},
      {"a draw takes 850 ns", "850 ns"},
      {"3.1 µs per triangle", "3.1 µs"},
      {"the run took 71 s.", "71 s"},
      {"in 71 seconds", "71 seconds"},
      {"a batch of 12 ms", "12 ms"},
      {"memset writes 9.6 GB/s", "9.6 GB/s"},
      {"it holds 14 MiB", "14 MiB"},
      {"reaches 70% of the write ceiling", "70% of the write ceiling"},
      {"2.5 times faster", "2.5 times faster"},
  };
  for (const auto& [text, found] : examples) {
    CAPTURE(text);
    CHECK(measured_looking(text) == found);
  }
}

TEST_CASE("Sizes, sample grids, counts and error rates do not look measured", "[listings]") {
  for (const std::string_view text : {
           "cut into 8×8 blocks",
           "a 256×256 canvas",
           "the 4 × 4 grid of samples",
           "the 8x8 block and the 16x16 grid",
           "the error rate is 0.233 over 14 scenes",
           "687 wrong pixels on 62 of 400 slivers",
           "x86-64 with AVX2, fixed_point_8 and 1/256 steps",
           "about 22% of the light",
           "the 1990s and chapter 7's oracle",
           "the value 0x1f",
       }) {
    CAPTURE(text);
    CHECK_FALSE(measured_looking(text));
  }
}

TEST_CASE("Only the READMEs that quote measurements are held to markers", "[listings]") {
  for (const std::string_view page :
       {"README.md", "chapters/08_fast_exact/README.md", "chapters/09_anti_aliasing/README.md",
        "chapters/10_speed_vs_error/README.md"}) {
    CAPTURE(page);
    CHECK(quotes_measurements(page));
  }
  for (const std::string_view page :
       {"chapters/07_exact_coverage/README.md", "chapters/08_fast_exact/notes/README.md",
        "docs/performance_notes.md"}) {
    CAPTURE(page);
    CHECK_FALSE(quotes_measurements(page));
  }
}

TEST_CASE("A measured number typed outside a marker fails the check, in code and markers not",
          "[listings]") {
  TempRepo repo;
  repo.write("docs/measurements/report_quick.csv", "key,value\nfast.speedup,3.2\n");
  const std::string allowed =
      "# Speed\n\n"
      "8×8 blocks on a 256×256 canvas, a 4 × 4 grid: "
      "<!-- measured: docs/measurements/report_quick.csv fast.speedup s2× -->3.2×"
      "<!-- /measured --> faster, `3.2× faster` in code.\n\n"
      "```text\n12 ms\n```\n";
  repo.write("chapters/10_speed_vs_error/README.md", allowed);
  repo.write("chapters/07_exact_coverage/README.md", "It is 3.2× faster.\n");
  CHECK(check_listings(repo.root()).problems.empty());

  repo.write("chapters/10_speed_vs_error/README.md", allowed + "\nIt is 3.2× faster.\n");
  repo.write("README.md",
             "| algorithm | Mpix/s |\n|---|--:|\n| fast | 1164 |\n\n"
             "<!-- measured-table: docs/measurements/report_quick.csv summary -->\n");
  const auto report = check_listings(repo.root());
  CHECK(any_problem_contains(report, "'3.2×' looks measured but is outside a measured marker"));
  CHECK(any_problem_contains(report, "a table of measurements outside a measured table block"));
  for (const auto& problem : report.problems) {
    if (problem.message.find("looks measured") != std::string::npos) {
      CHECK(problem.file == "chapters/10_speed_vs_error/README.md");
      CHECK(problem.line == 9);
      CHECK_FALSE(problem.refreshable);
    }
  }
}

}  // namespace tri::listings::testing
