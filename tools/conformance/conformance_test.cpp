#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "chapters/07_exact_coverage/coverage_oracle.hpp"
#include "chapters/11_your_rasterizer/conformance_app.hpp"
#include "chapters/11_your_rasterizer/grading.hpp"
#include "chapters/11_your_rasterizer/named_tests.hpp"
#include "measure/registry.hpp"
#include "tests/support/in_process_run.hpp"
#include "tests/support/scratch_folder.hpp"

namespace fs = std::filesystem;
using namespace tri;
using namespace tri::conformance;

namespace {

using Run = testing::InProcessRun;

Run run_program(const std::vector<std::string>& args) {
  return testing::run_in_process(
      "conformance", args,
      [](int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
        return run_conformance(argc, argv, out, err);
      });
}

std::set<std::string> failed_tests(const GradedRasterizer& rasterizer, TieRule rule) {
  std::set<std::string> failed;
  for (const TestResult& r : grade_all(named_tests(), rasterizer, rule)) {
    if (!r.passed) failed.insert(r.test);
  }
  return failed;
}

std::set<std::string> all_test_names() {
  std::set<std::string> names;
  for (const NamedTest& t : named_tests()) names.insert(t.name);
  return names;
}

// Chapter 07's oracle with the scene mirrored top to bottom: the bottom-left rule.
void bottom_left_fill(Canvas& canvas, const Triangle& t, Color color) {
  Canvas mirrored(canvas.width(), canvas.height());
  mirrored.enable_write_counts();
  Triangle m = t;
  for (auto& v : m) v.y = (canvas.height() - 1) - v.y;
  ch07::draw_triangle_oracle(mirrored, m, color);
  for (int y = 0; y < canvas.height(); ++y) {
    for (int x = 0; x < canvas.width(); ++x) {
      for (std::uint32_t i = 0; i < mirrored.write_count(x, canvas.height() - 1 - y); ++i) {
        canvas.put_pixel(x, y, color);
      }
    }
  }
}

}  // namespace

TEST_CASE("Every registered algorithm that claims the top-left rule passes every named test",
          "[conformance]") {
  int graded = 0;
  for (const TriangleAlgorithm& algorithm : registered_algorithms()) {
    if (algorithm.rule != CoverageRule::top_left) continue;
    INFO(algorithm.name);
    CHECK(failed_tests(graded_algorithm(algorithm), TieRule::top_left).empty());
    ++graded;
  }
  CHECK(graded >= 10);  // the oracle, fixed_point_8 and chapter 08's variants
}

TEST_CASE("The articles' fills of chapters 03 to 06 fail exactly the tests their chapters explain",
          "[conformance]") {
  // Every one rounds its vertices to pixel centres (random triangles, hard cases, range) and keeps
  // centres on every edge (tie rule, watertight meshes: shared edges drawn twice). Chapter 04's
  // two loops depend on the vertex order; the articles' fills of chapters 03 to 05 draw zero-area
  // triangles, chapter 06 guards against them; chapter 03's float interpolation rounds ties
  // differently once a scene moves.
  const std::set<std::string> common{"hard_cases", "random_triangles", "watertight_meshes",
                                     "tie_rule",   "range_32768",      "range_2_30"};
  const auto with = [&common](std::set<std::string> more) {
    more.insert(common.begin(), common.end());
    return more;
  };
  const std::map<std::string, std::set<std::string>> expected{
      {"gambetta_interpolate_fill", with({"degenerate", "translation"})},
      {"scanline_two_loops", with({"degenerate", "vertex_order"})},
      {"scanline_single_loop", with({"degenerate"})},
      {"edge_function", with({"degenerate"})},
      {"barycentric_float", common},
      {"barycentric_double", common},
  };
  const std::set<std::string> chapters{"03_interpolate_fill", "04_scanline", "05_edge_function",
                                       "06_barycentric"};
  std::size_t graded = 0;
  for (const TriangleAlgorithm& algorithm : registered_algorithms()) {
    if (!chapters.contains(std::string(algorithm.chapter))) continue;
    INFO(algorithm.name);
    REQUIRE(expected.contains(std::string(algorithm.name)));
    CHECK(failed_tests(graded_algorithm(algorithm), TieRule::top_left) ==
          expected.at(std::string(algorithm.name)));
    ++graded;
  }
  CHECK(graded == expected.size());
}

TEST_CASE("The bottom-left rule is the top-left rule mirrored: each passes its own grading only",
          "[conformance]") {
  const GradedRasterizer mirrored = graded_fill("bottom-left oracle", bottom_left_fill);
  CHECK(failed_tests(mirrored, TieRule::bottom_left).empty());
  CHECK(failed_tests(mirrored, TieRule::any).empty());
  // Against the top-left rule only the ties differ: the single-triangle tests with centres on
  // edges. Meshes stay watertight and every relation holds.
  CHECK(failed_tests(mirrored, TieRule::top_left) ==
        std::set<std::string>{"hard_cases", "tie_rule"});
  const GradedRasterizer oracle = graded_fill("oracle", ch07::draw_triangle_oracle);
  CHECK(failed_tests(oracle, TieRule::bottom_left) ==
        std::set<std::string>{"hard_cases", "tie_rule"});
  CHECK(failed_tests(oracle, TieRule::any).empty());
}

TEST_CASE("Under the rule any, an inclusive fill fails the watertight meshes and the tie rule",
          "[conformance]") {
  // Every centre on an edge covered: each tie alone is some rule's, shared edges are drawn twice.
  const auto inclusive = [](Canvas& canvas, const Triangle& t, Color color) {
    const Triangle ccw = ch07::counter_clockwise(t);
    const auto side = [](glm::dvec2 a, glm::dvec2 b, glm::dvec2 p) {
      return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
    };
    if (side(ccw[0], ccw[1], ccw[2]) == 0) return;  // no area
    for (int y = 0; y < canvas.height(); ++y) {
      for (int x = 0; x < canvas.width(); ++x) {
        const glm::dvec2 p(x, y);
        if (side(ccw[0], ccw[1], p) >= 0 && side(ccw[1], ccw[2], p) >= 0 &&
            side(ccw[2], ccw[0], p) >= 0) {
          canvas.put_pixel(x, y, color);
        }
      }
    }
  };
  const std::set<std::string> failed =
      failed_tests(graded_fill("inclusive", inclusive), TieRule::any);
  CHECK(failed.contains("watertight_meshes"));
  CHECK(failed.contains("tie_rule"));
  CHECK_FALSE(failed.contains("vertex_order"));
  CHECK_FALSE(failed.contains("determinism"));
}

TEST_CASE("An empty fill fails every test that expects pixels and passes the others",
          "[conformance]") {
  const auto nothing = [](Canvas&, const Triangle&, Color) {};
  const std::set<std::string> failed =
      failed_tests(graded_fill("empty", nothing), TieRule::top_left);
  CHECK(failed == std::set<std::string>{"hard_cases", "random_triangles", "watertight_meshes",
                                        "tie_rule", "range_32768", "range_2_30"});
}

TEST_CASE("A scorecard holds one CSV row per test and a diagram of each failure's smallest case",
          "[conformance]") {
  tri::testing::ScratchFolder folder("conformance_scorecard");
  const Run run = run_program({"--algo", "edge_function", "--out", folder.path().string()});
  CHECK(run.status == 1);
  CHECK(run.err ==
        "conformance: 7 of 11 tests failed: hard_cases, random_triangles, watertight_meshes, "
        "tie_rule, range_32768, range_2_30, degenerate\n");
  const std::string csv = tri::testing::read_text(folder / "scorecard.csv");
  std::istringstream lines(csv);
  std::string line;
  std::getline(lines, line);
  CHECK(line == "test,verdict,missed,extra,doubled,detail");
  std::set<std::string> failed, passed;
  while (std::getline(lines, line)) {
    const auto first = line.find(','), second = line.find(',', first + 1);
    (line.substr(first + 1, second - first - 1) == "fail" ? failed : passed)
        .insert(line.substr(0, first));
  }
  CHECK(failed.size() == 7);
  CHECK(failed.size() + passed.size() == all_test_names().size());
  CHECK(csv.find("tie_rule,fail,0,259,110,\"10 of 11 cases wrong; smallest: \"\"flat top on "
                 "centres\"\"\"") != std::string::npos);
  // A diagram per failure, none for a pass; the Markdown links each.
  std::vector<std::string> expected_files{"scorecard.csv", "scorecard.md"};
  for (const auto& name : failed) expected_files.push_back(name + ".svg");
  std::sort(expected_files.begin(), expected_files.end());
  CHECK(tri::testing::names_in(folder.path()) == expected_files);
  const std::string markdown = tri::testing::read_text(folder / "scorecard.md");
  for (const auto& name : failed) CHECK(markdown.find("](" + name + ".svg)") != std::string::npos);
  const std::string svg = tri::testing::read_text(folder / "tie_rule.svg");
  CHECK(svg.starts_with("<svg"));
  CHECK(svg.find("extra (") != std::string::npos);
}

TEST_CASE("conformance passes the oracle with exit status 0 and a row per passed test",
          "[conformance]") {
  const Run run = run_program({"--algo", "exact_oracle"});
  CHECK(run.status == 0);
  CHECK(run.err.empty());
  for (const auto& name : all_test_names()) {
    CHECK(run.out.find("\n" + name + std::string(18 - name.size(), ' ') + " pass") !=
          std::string::npos);
  }
}

TEST_CASE("conformance refuses a bad command line with exit status 2 and does nothing",
          "[conformance]") {
  tri::testing::ScratchFolder folder("conformance_usage");
  const std::string out = (folder / "card").string();
  for (const auto& args : std::vector<std::vector<std::string>>{
           {"--out", out},
           {"--algo", "exact_oracle", "--command", "x {scene} {counts}", "--out", out},
           {"--algo", "no_such_algorithm", "--out", out},
           {"--algo", "area_cells", "--out", out},
           {"--algo", "exact_oracle", "--rule", "top-right", "--out", out},
           {"--command", "prog {scene}", "--out", out},
           {"--command", "prog '{scene} {counts}", "--out", out}}) {
    const Run run = run_program(args);
    INFO(run.err);
    CHECK(run.status == 2);
    CHECK(run.err.starts_with("conformance: error: "));
    CHECK_FALSE(fs::exists(out));
  }
  CHECK(run_program({"--algo", "area_cells"}).err.find("anti-aliasing") != std::string::npos);
}
