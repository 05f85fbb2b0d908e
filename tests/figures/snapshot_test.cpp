// The speed-vs-error plot is committed as the snapshot of one timed run, so it cannot be
// compared byte for byte; its structure can: a whole SVG document that shows every registered
// algorithm and the ceiling the text measures against.
#include <catch2/catch.hpp>

#include <fstream>
#include <iterator>
#include <string>

#include "measure/registry.hpp"

TEST_CASE(
    "The committed speed-vs-error snapshot is a whole SVG that names every registered algorithm",
    "[figures]") {
  std::ifstream in(TUTORIAL_COMMITTED_FIGURES "/09_speed_vs_error.svg", std::ios::binary);
  REQUIRE(in);
  const std::string svg((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(svg.starts_with("<svg"));
  CHECK(svg.find("</svg>") != std::string::npos);
  // The ceiling of measure/fill_ceiling.hpp, not the std::fill reference of older snapshots.
  CHECK(svg.find("write ceiling (memset, vector stores), 1 thread: ") != std::string::npos);
  for (const auto& algorithm : tri::registered_algorithms()) {
    INFO("algorithm " << algorithm.name
                      << " is missing from docs/figures/09_speed_vs_error.svg: refresh the "
                         "snapshot from a run of 09_speed_vs_error (see chapter 09's README)");
    const std::string label = ">" + std::string(algorithm.name);
    const bool shown =
        svg.find(label + "<") != std::string::npos || svg.find(label + " (") != std::string::npos;
    CHECK(shown);
  }
}
