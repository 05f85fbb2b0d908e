#include "common/figures.hpp"

#include "tests/support/scratch_folder.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace tri {
namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

SvgFigure first_figure() {
  return {"01_first", "<svg>first</svg>"};
}
SvgFigure second_figure() {
  return {"01_second", "<svg>second</svg>"};
}

TEST_CASE("A chapter program saves each SVG figure under the name its function gives",
          "[common][figures]") {
  const testing::ScratchFolder scratch("figures");
  const fs::path folder = scratch / "figures";  // made by the program
  const std::string out = folder.string();
  const char* argv[] = {"01_test", "--out", out.c_str()};
  REQUIRE(run_chapter_program(3, argv, "01_test", "Two test figures.",
                              {first_figure, second_figure}) == 0);
  CHECK(read(folder / "01_first.svg") == "<svg>first</svg>");
  CHECK(read(folder / "01_second.svg") == "<svg>second</svg>");
  CHECK(std::distance(fs::directory_iterator(folder), fs::directory_iterator()) == 2);
}

TEST_CASE("A chapter program answers --help without drawing a figure", "[common][figures]") {
  bool drawn = false;
  const char* argv[] = {"01_test", "--help"};
  CHECK(run_chapter_program(2, argv, "01_test", "Two test figures.", {[&] {
                              drawn = true;
                              return first_figure();
                            }}) == 0);
  CHECK_FALSE(drawn);
}

}  // namespace
}  // namespace tri
