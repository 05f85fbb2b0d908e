#include "tools/listings/unmarked.hpp"

#include <catch2/catch.hpp>

#include <string>

#include "tools/listings/listings.hpp"
#include "tools/listings/temp_repo.hpp"

using namespace tri::listings;
using tri::listings::testing::any_problem_contains;
using tri::listings::testing::TempRepo;

TEST_CASE("Times, rates, ratios and shares of a ceiling look measured", "[listings]") {
  CHECK(measured_looking("the span walker is 3.2× faster") == "3.2×");
  CHECK(measured_looking("3x faster than the oracle") == "3x");
  CHECK(measured_looking("it fills 1164 Mpix/s on large triangles") == "1164 Mpix/s");
  CHECK(measured_looking("at 15.9 Mtri/s") == "15.9 Mtri/s");
  CHECK(measured_looking("about 6.68 M tris/s on tiny ones") == "6.68 M tris/s");
  CHECK(measured_looking("22.5 tris/s") == "22.5 tris/s");
  CHECK(measured_looking("a draw takes 850 ns") == "850 ns");
  CHECK(measured_looking("3.1 µs per triangle") == "3.1 µs");
  CHECK(measured_looking("the run took 71 s.") == "71 s");
  CHECK(measured_looking("in 71 seconds") == "71 seconds");
  CHECK(measured_looking("a batch of 12 ms") == "12 ms");
  CHECK(measured_looking("memset writes 9.6 GB/s") == "9.6 GB/s");
  CHECK(measured_looking("it holds 14 MiB") == "14 MiB");
  CHECK(measured_looking("reaches 70% of the write ceiling") == "70% of the write ceiling");
  CHECK(measured_looking("2.5 times faster") == "2.5 times faster");
}

TEST_CASE("Sizes, sample grids, counts and error rates do not look measured", "[listings]") {
  CHECK_FALSE(measured_looking("cut into 8×8 blocks"));
  CHECK_FALSE(measured_looking("a 256×256 canvas"));
  CHECK_FALSE(measured_looking("the 4 × 4 grid of samples"));
  CHECK_FALSE(measured_looking("the 8x8 block and the 16x16 grid"));
  CHECK_FALSE(measured_looking("the error rate is 0.233 over 14 scenes"));
  CHECK_FALSE(measured_looking("687 wrong pixels on 62 of 400 slivers"));
  CHECK_FALSE(measured_looking("x86-64 with AVX2, fixed_point_8 and 1/256 steps"));
  CHECK_FALSE(measured_looking("about 22% of the light"));
  CHECK_FALSE(measured_looking("the 1990s and chapter 7's oracle"));
  CHECK_FALSE(measured_looking("the value 0x1f"));
}

TEST_CASE("Only the READMEs that quote measurements are held to markers", "[listings]") {
  CHECK(quotes_measurements("README.md"));
  CHECK(quotes_measurements("chapters/08_fast_exact/README.md"));
  CHECK(quotes_measurements("chapters/09_anti_aliasing/README.md"));
  CHECK(quotes_measurements("chapters/10_speed_vs_error/README.md"));
  CHECK_FALSE(quotes_measurements("chapters/07_exact_coverage/README.md"));
  CHECK_FALSE(quotes_measurements("chapters/08_fast_exact/notes/README.md"));
  CHECK_FALSE(quotes_measurements("docs/performance_notes.md"));
}

TEST_CASE("A measured number typed outside a marker fails the check; code and markers do not",
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
