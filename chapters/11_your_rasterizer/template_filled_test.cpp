// The template filled with a correct fill (chapter 07's oracle, written into its body by the
// build): graded, it passes every test and needs no hint.
#include <catch2/catch.hpp>

#include <sstream>

#include "chapters/11_your_rasterizer/grade_your_fill.hpp"
#include "chapters/11_your_rasterizer/template_support.hpp"
#include "tests/support/scratch_folder.hpp"

TEST_CASE("Filled with a correct fill, the template passes every test of the suite",
          "[11_your_rasterizer][step3]") {
  const tri::testing::ScratchFolder scratch("template_filled");
  std::ostringstream out, err;
  CHECK(tri::ch11::grade_your_fill(tri::conformance::TieRule::top_left, scratch.path(), out, err) ==
        0);
  CHECK(err.str().empty());
  CHECK(std::filesystem::exists(scratch.path() / "scorecard.md"));
  CHECK(tri::ch11::test::failed_in_scorecard(scratch.path()).empty());
  CHECK(out.str().find("determinism") != std::string::npos);  // a row per test, the last one too
}
