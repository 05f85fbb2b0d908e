// The speed-vs-error plot and the scaling plots are committed as snapshots of one timed run, so
// they cannot be compared byte for byte; their structure can: whole SVG documents that show every
// registered algorithm and the ceiling the text measures against, or every drawer of the sweeps.
#include <catch2/catch.hpp>

#include <fstream>
#include <iterator>
#include <string>

#include "measure/registry.hpp"

TEST_CASE(
    "The committed speed-vs-error snapshot is a whole SVG that names every registered algorithm",
    "[figures]") {
  std::ifstream in(TUTORIAL_COMMITTED_FIGURES "/10_speed_vs_error.svg", std::ios::binary);
  REQUIRE(in);
  const std::string svg((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(svg.starts_with("<svg"));
  CHECK(svg.find("</svg>") != std::string::npos);
  // The ceiling of measure/fill_ceiling.hpp, not the std::fill reference of older snapshots.
  CHECK(svg.find("write ceiling (memset, vector stores), 1 thread: ") != std::string::npos);
  for (const auto& algorithm : tri::registered_algorithms()) {
    INFO("algorithm " << algorithm.name
                      << " is missing from docs/figures/10_speed_vs_error.svg: refresh the "
                         "snapshot from a run of 10_speed_vs_error (see chapter 10's README)");
    const std::string label = ">" + std::string(algorithm.name);
    const bool shown =
        svg.find(label + "<") != std::string::npos || svg.find(label + " (") != std::string::npos;
    CHECK(shown);
  }
}

TEST_CASE("The committed scaling snapshots are whole SVGs of fast_hybrid, the ceiling and the peers",
          "[figures]") {
  for (const char* name : {"10_scaling_triangles.svg", "10_scaling_canvas.svg"}) {
    INFO(name << ": refresh the snapshot from a --full run of 10_speed_vs_error (chapter 10, "
                 "step 9)");
    std::ifstream in(std::string(TUTORIAL_COMMITTED_FIGURES "/") + name, std::ios::binary);
    REQUIRE(in);
    const std::string svg((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    CHECK(svg.starts_with("<svg"));
    CHECK(svg.find("</svg>") != std::string::npos);
    CHECK(svg.find(">fast_hybrid<") != std::string::npos);
    for (const char* peer : {">pixman_a1<", ">cairo_no_antialias<", ">mesa_llvmpipe_1_thread<"}) {
      CHECK(svg.find(peer) != std::string::npos);
    }
  }
  std::ifstream in(TUTORIAL_COMMITTED_FIGURES "/10_scaling_canvas.svg", std::ios::binary);
  const std::string canvas((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(canvas.find(">write_ceiling<") != std::string::npos);
}
