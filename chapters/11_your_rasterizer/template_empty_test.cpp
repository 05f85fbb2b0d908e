// The template as the learner finds it: graded, it fails what expects pixels and says why.
#include <catch2/catch.hpp>

#include <sstream>

#include "chapters/11_your_rasterizer/grade_your_fill.hpp"
#include "chapters/11_your_rasterizer/template_support.hpp"
#include "tests/support/scratch_folder.hpp"

TEST_CASE(
    "Left empty, the template fails every test that expects pixels and says what to write first",
    "[11_your_rasterizer][step2]") {
  const tri::testing::ScratchFolder scratch("template_empty");
  std::ostringstream out, err;
  CHECK(tri::ch11::grade_your_fill(tri::conformance::TieRule::top_left, scratch.path(), out, err) ==
        1);
  CHECK_THAT(err.str(), Catch::Contains("your_fill draws no pixel yet") &&
                            Catch::Contains("chapters/11_your_rasterizer/your_fill.cpp"));
  CHECK(tri::ch11::test::failed_in_scorecard(scratch.path()) ==
        std::set<std::string>{"hard_cases", "random_triangles", "watertight_meshes", "tie_rule",
                              "range_32768", "range_2_30"});
}
