// fuzz_coverage's checks, run in every test run with the normal compiler: on every seed of its
// corpus and of fuzz_rasterizers' corpus, with every coverage algorithm; on every past finding
// (one named TEST_CASE each); and on deliberately broken algorithms, so the checks are known to
// catch what they claim to.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "chapters/09_anti_aliasing/area_algorithms.hpp"
#include "fuzz/coverage_check.hpp"
#include "fuzz/coverage_seeds.hpp"
#include "fuzz/rasterizer_input.hpp"
#include "fuzz/regressions/corpus_files.hpp"

namespace tri::fuzz {
namespace {

namespace fs = std::filesystem;

// What fuzz_coverage checks, applied with every coverage algorithm instead of the one the input's
// first byte picks, so a seed or finding guards each algorithm.
void require_coverage_checks_hold(const RasterizerInput& decoded) {
  const RasterizerInput input = coverage_input(decoded);
  for (const ch09::AreaAlgorithm& algorithm : ch09::area_algorithms()) {
    INFO("algorithm " << algorithm.name);
    CHECK(check_coverage(algorithm, input) == Findings{});
  }
}

void require_coverage_checks_hold(std::span<const std::uint8_t> bytes) {
  require_coverage_checks_hold(decode_rasterizer_input(bytes));
}

// One input of the given triangles, raw doubles, on a size x size canvas.
RasterizerInput input_of(int size, const std::vector<Triangle>& triangles) {
  RasterizerInput input;
  input.width = input.height = size;
  for (const Triangle& t : triangles) input.triangles.push_back({t, colors::white});
  return input;
}

// Changes that break area_cells on purpose: a pixel outside the test triangles (exactly 0) made
// 2e-6, or -0.5.
void add_a_little_at_6_6(ch09::CoverageCanvas& canvas) {
  canvas.add(6, 6, 2e-6f);
}
void set_minus_a_half_at_0_0(ch09::CoverageCanvas& canvas) {
  canvas.set(0, 0, -0.5f);
}

// A deliberately broken algorithm: area_cells, then `change` on the canvas.
template <void (*change)(ch09::CoverageCanvas&)>
void area_cells_then(ch09::CoverageCanvas& canvas, std::span<const SceneTriangle> triangles) {
  ch09::area_algorithms()[0].draw(canvas, triangles);
  change(canvas);
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// The seed corpus.

TEST_CASE("Every coverage seed keeps the coverage checks with every coverage algorithm",
          "[fuzz][corpus]") {
  int files = 0;
  for (const char* target : {"fuzz_coverage", "fuzz_rasterizers"}) {
    for (const auto& entry : fs::directory_iterator(corpus_folder / target)) {
      INFO("seed " << target << "/" << entry.path().filename().string());
      require_coverage_checks_hold(read_bytes(entry.path()));
      ++files;
    }
  }
  CHECK(files >= static_cast<int>(coverage_seeds().size()) + 25);
}

TEST_CASE("The coverage seeds in the repository are the ones fuzz_seed_writer writes",
          "[fuzz][corpus]") {
  const auto seeds = coverage_seeds();
  CHECK(seeds.size() >= 10);
  for (const NamedSeed& seed : seeds) {
    INFO("seed " << seed.name << " (rewrite the corpus with fuzz_seed_writer)");
    CHECK(read_bytes(corpus_folder / "fuzz_coverage" / seed.name) == seed.bytes);
  }
}

TEST_CASE("A coverage input's canvas is cut to at most 16x16", "[fuzz][layout]") {
  RasterizerInput input;
  input.width = 64;
  input.height = 17;
  const RasterizerInput cut = coverage_input(input);
  CHECK(cut.width == 16);
  CHECK(cut.height == 1);
  input.width = 16;
  CHECK(coverage_input(input).width == 16);
}

// ---------------------------------------------------------------------------------------------
// The checks catch what they claim to (each broken algorithm must be reported).

TEST_CASE("The coverage checks report an exact-area algorithm off the exact area",
          "[fuzz][checks]") {
  ch09::AreaAlgorithm broken = ch09::area_algorithms()[0];
  broken.draw = area_cells_then<add_a_little_at_6_6>;
  const Findings findings = check_coverage(broken, input_of(8, {{{{1, 1}, {7, 2}, {3, 7}}}}));
  REQUIRE(findings.size() == 1);
  CHECK_THAT(findings[0], Catch::Contains("unlike the exact area 1: (6, 6)"));
}

TEST_CASE("The coverage checks report a sampling algorithm unlike its own samples",
          "[fuzz][checks]") {
  ch09::AreaAlgorithm broken = ch09::area_algorithms()[4];  // 4x4 samples, drawn as exact area
  broken.draw = ch09::area_algorithms()[0].draw;
  const Findings findings = check_coverage(broken, input_of(8, {{{{1, 1}, {7, 2}, {3, 7}}}}));
  REQUIRE(findings.size() == 1);
  CHECK_THAT(findings[0], Catch::Contains("unlike its own samples' count"));
}

TEST_CASE("The coverage checks report coverage outside [0, 1]", "[fuzz][checks]") {
  ch09::AreaAlgorithm broken = ch09::area_algorithms()[0];
  broken.draw = area_cells_then<set_minus_a_half_at_0_0>;
  const Findings findings = check_coverage(broken, input_of(4, {{{{1, 1}, {3, 1}, {1, 3}}}}));
  REQUIRE(findings.size() == 2);
  CHECK_THAT(findings[0], Catch::Contains("outside [0, 1]"));
  CHECK_THAT(findings[1], Catch::Contains("unlike the exact area"));
}

TEST_CASE("The coverage checks report a scene unlike its triangles drawn one by one",
          "[fuzz][checks]") {
  ch09::AreaAlgorithm broken = ch09::area_algorithms()[2];  // 1 sample: whole pixels
  broken.draw = [](ch09::CoverageCanvas& canvas, std::span<const SceneTriangle> triangles) {
    ch09::area_algorithms()[2].draw(canvas, triangles.first(1));  // draws only the first
  };
  const Findings findings =
      check_coverage(broken, input_of(8, {{{{1, 1}, {7, 1}, {1, 7}}}, {{{7, 1}, {7, 7}, {1, 7}}}}));
  REQUIRE(findings.size() == 1);
  CHECK_THAT(findings[0], Catch::Contains("unlike the triangles drawn one by one"));
}

TEST_CASE("The coverage checks compare with the oracle only near the 1/256 grid",
          "[fuzz][checks]") {
  ch09::AreaAlgorithm broken = ch09::area_algorithms()[0];
  broken.draw = area_cells_then<add_a_little_at_6_6>;
  // 1/3 is 1/768 from the grid: no exact truth to compare with, so nothing is reported.
  CHECK(check_coverage(broken, input_of(8, {{{{1.0 / 3, 1}, {7, 2}, {3, 7}}}})) == Findings{});
  // 1e-310 from the grid: compared with the grid triangle, and reported.
  CHECK(check_coverage(broken, input_of(8, {{{{1e-310, 1}, {7, 2}, {3, 7}}}})).size() == 1);
}

// ---------------------------------------------------------------------------------------------
// Findings, one named TEST_CASE each (see README.md).

TEST_CASE("fuzz finding: area_cells_over crashed on two vertices a subnormal distance apart",
          "[fuzz][finding]") {
  require_coverage_checks_hold(input_of(16, {{{{15, 0}, {1e-310, 1e-310}, {0, 15}}}}));
}

TEST_CASE("fuzz finding: area_cells left 19 pixels empty for a vertex 1e-310 off the grid",
          "[fuzz][finding]") {
  require_coverage_checks_hold(input_of(16, {{{{15, 0}, {0, 0}, {1e-310, 15}}}}));
}

TEST_CASE("fuzz finding: area_cells left pixel (1, 1) empty for a vertex 2^-1074 off the grid",
          "[fuzz][finding]") {
  require_coverage_checks_hold(input_of(16, {{{{0, 0}, {10, 5}, {4.9406564584124654e-324, 10}}}}));
}

}  // namespace tri::fuzz
