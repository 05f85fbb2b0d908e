// The golden-figure check itself: it must catch one changed pixel, one changed byte, a figure
// nobody committed, a committed figure nobody renders, and a README image that is not a file.
#include "tests/figures/figure_comparison.hpp"

#include <catch2/catch.hpp>

#include <fstream>
#include <random>

#include "common/canvas.hpp"
#include "common/image_io.hpp"

namespace {
namespace fs = std::filesystem;

// A fresh, empty folder under the system's temporary folder, removed at the end of the test.
struct ScratchFolder {
  fs::path path;
  ScratchFolder() {
    std::random_device seed;
    path = fs::temp_directory_path() / ("figure_comparison_" + std::to_string(seed()));
    fs::create_directories(path);
  }
  ~ScratchFolder() { fs::remove_all(path); }
};

void write_text(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
}

tri::Canvas small_picture() {
  tri::Canvas canvas(8, 6, tri::colors::black);
  canvas.put_pixel(2, 3, tri::colors::yellow);
  return canvas;
}

// Two folders holding the same PNG and SVG.
struct TwoFolders {
  ScratchFolder scratch;
  fs::path rendered = scratch.path / "rendered", committed = scratch.path / "committed";
  TwoFolders() {
    for (const auto& folder : {rendered, committed}) {
      tri::write_png(small_picture(), folder / "picture.png");
      write_text(folder / "diagram.svg", "<svg>\n<rect/>\n</svg>\n");
    }
  }
};

bool any_names(const std::vector<std::string>& problems, const std::string& text) {
  for (const auto& p : problems) {
    if (p.find(text) != std::string::npos) return true;
  }
  return false;
}

}  // namespace

TEST_CASE("Golden figures: identical rendered and committed figures pass", "[figures]") {
  const TwoFolders folders;
  CHECK(tri::figures::compare_figures(folders.rendered, folders.committed).empty());
}

TEST_CASE("Golden figures: one changed pixel of a PNG fails, naming the figure and the pixel",
          "[figures]") {
  const TwoFolders folders;
  tri::Canvas changed = small_picture();
  changed.put_pixel(5, 1, tri::Color{0, 0, 1, 255});  // one channel of one pixel, by one
  tri::write_png(changed, folders.rendered / "picture.png");
  const auto problems = tri::figures::compare_figures(folders.rendered, folders.committed);
  REQUIRE(problems.size() == 1);
  CHECK(problems[0] ==
        "picture.png: differs in 1 pixel(s), first at image pixel (5, 1) counted from the "
        "bottom-left");
}

TEST_CASE("Golden figures: one changed byte of an SVG fails, naming the figure and the line",
          "[figures]") {
  const TwoFolders folders;
  write_text(folders.rendered / "diagram.svg", "<svg>\n<rekt/>\n</svg>\n");
  const auto problems = tri::figures::compare_figures(folders.rendered, folders.committed);
  REQUIRE(problems.size() == 1);
  CHECK(problems[0] == "diagram.svg: differs from the committed file at byte 9 (line 2)");
}

TEST_CASE("Golden figures: a rendered figure that was never committed fails", "[figures]") {
  const TwoFolders folders;
  write_text(folders.rendered / "new.svg", "<svg/>\n");
  const auto problems = tri::figures::compare_figures(folders.rendered, folders.committed);
  REQUIRE(problems.size() == 1);
  CHECK(any_names(problems, "new.svg: rendered but not committed"));
}

TEST_CASE(
    "Golden figures: a committed figure that no program renders is stale, unless it is a snapshot "
    "of a timed run",
    "[figures]") {
  const TwoFolders folders;
  write_text(folders.committed / "old.svg", "<svg/>\n");
  write_text(folders.committed / "10_plot.svg", "<svg/>\n");
  const auto problems =
      tri::figures::stale_figures(folders.committed, {folders.rendered}, {"10_plot.svg"});
  REQUIRE(problems.size() == 1);
  CHECK(any_names(problems, "old.svg: committed in"));
}

TEST_CASE("Golden figures: every README image must be an existing file inside the repository",
          "[figures]") {
  const ScratchFolder scratch;
  const fs::path root = scratch.path / "repo";
  write_text(root / "docs/figures/a.svg", "<svg/>\n");
  const fs::path good = root / "chapters/01/README.md";
  write_text(good, "Text ![A figure](../../docs/figures/a.svg) more.\n");
  CHECK(tri::figures::missing_images(root, {good}).empty());

  const fs::path bad = root / "chapters/02/README.md";
  write_text(bad,
             "![missing](../../docs/figures/b.svg)\n"
             "![build output](a.svg \"only in the build folder\")\n"
             "![web](https://example.org/a.png)\n"
             "![outside](../../../elsewhere.svg)\n");
  const auto problems = tri::figures::missing_images(root, {bad});
  REQUIRE(problems.size() == 4);
  CHECK(any_names(problems, "README.md:1: ../../docs/figures/b.svg does not exist"));
  CHECK(any_names(problems, "README.md:2: a.svg does not exist"));
  CHECK(any_names(problems, "README.md:3: https://example.org/a.png is not a file"));
  CHECK(any_names(problems, "README.md:4: ../../../elsewhere.svg points outside"));
}
