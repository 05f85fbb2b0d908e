// An algorithm added the way a chapter adds one (centres_in_box.cpp: its function and its entry)
// is found by raster, the hard-case matrix and the report, through the same library functions,
// with the registry extended by that entry and the global registrations untouched.
#include <catch2/catch.hpp>

#include <algorithm>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include "chapters/10_speed_vs_error/measure.hpp"
#include "chapters/10_speed_vs_error/report.hpp"
#include "measure/hard_cases.hpp"
#include "measure/machine.hpp"
#include "measure/peers/external_peers.hpp"
#include "measure/registry.hpp"
#include "tests/support/in_process_run.hpp"
#include "tests/support/scratch_folder.hpp"
#include "tools/raster_app.hpp"

namespace tri::one_file {
std::span<const TriangleAlgorithm> triangle_algorithms();  // centres_in_box.cpp's registration
}  // namespace tri::one_file

namespace {

// The registry's drawables with this target's one entry added, as a chapter's list is.
std::vector<tri::Drawable> extended_drawables() {
  std::vector<tri::Drawable> drawables = tri::registered_drawables();
  for (const tri::TriangleAlgorithm& a : tri::one_file::triangle_algorithms())
    drawables.push_back(tri::describe(a));
  return drawables;
}

const tri::TriangleAlgorithm& added() {
  REQUIRE(tri::one_file::triangle_algorithms().size() == 1);
  return tri::one_file::triangle_algorithms().front();
}

using Run = tri::testing::InProcessRun;

Run raster(std::span<const tri::Drawable> drawables, const std::vector<std::string>& args) {
  return tri::testing::run_in_process(
      "raster", args,
      [drawables](int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
        return tri::run_raster(drawables, argc, argv, out, err);
      });
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

TEST_CASE("An algorithm registered in one file is listed and drawn by raster",
          "[one_file_algorithm]") {
  const auto drawables = extended_drawables();
  const Run listed = raster(drawables, {"--list"});
  REQUIRE(listed.status == 0);
  const auto lines = lines_of(listed.out);
  CHECK(lines.size() == drawables.size());
  CHECK(lines.back() == std::string(added().name) + "\tone_file_algorithm\tapproximate\t" +
                            std::string(added().summary));
  // The global registry knows nothing of it.
  CHECK(raster(tri::registered_drawables(), {"--list"}).out.find(added().name) ==
        std::string::npos);

  tri::testing::ScratchFolder folder("one_file_algorithm");
  tri::testing::write_text(folder / "one.scene", "canvas 8 8\ntri 1 1 6 1 1 6\n");
  const std::string scene = (folder / "one.scene").string();
  const std::string counts = (folder / "counts.pgm").string();
  const std::string name(added().name);
  const Run drawn = raster(
      drawables, {"--algo", name.c_str(), "--scene", scene.c_str(), "--counts", counts.c_str()});
  REQUIRE(drawn.status == 0);
  CHECK(drawn.out == "drew 1 triangle(s) and 0 line(s) on 8x8 with " + name + "\n");
  const std::string pgm = tri::testing::read_text(folder / "counts.pgm");
  const std::string pixels = pgm.substr(pgm.size() - 64);
  // The right triangle with legs of 5 pixels covers 6 + 5 + ... + 1 centres, edges included.
  CHECK(std::count(pixels.begin(), pixels.end(), '\1') == 21);
  // What it did not declare, it is not asked for.
  CHECK(raster(drawables, {"--algo", name.c_str(), "--scene", scene.c_str(), "--format", "mask1"})
            .status != 0);
}

TEST_CASE("An algorithm registered in one file has a row per case in the hard-case matrix",
          "[one_file_algorithm]") {
  const auto drawables = extended_drawables();
  const auto outcomes = tri::hard_cases::run_all(tri::colour_algorithms(drawables));
  const auto cases = tri::hard_cases::all_cases();
  const auto own = std::count_if(outcomes.begin(), outcomes.end(),
                                 [&](const auto& o) { return o.algorithm == added().name; });
  CHECK(static_cast<std::size_t>(own) == cases.size());
  for (const auto& o : outcomes) {
    if (o.algorithm != added().name) continue;
    INFO(o.case_name);
    CHECK(o.safe);
    CHECK(o.rule == "approximate");
  }
  CHECK(tri::hard_cases::to_csv(outcomes).find(std::string(added().name) + ",") !=
        std::string::npos);
}

TEST_CASE("An algorithm registered in one file has its row in the report's table",
          "[one_file_algorithm]") {
  const auto drawables = extended_drawables();
  const std::vector<tri::TriangleAlgorithm> measured{added()};
  const tri::ch10::BenchSettings settings = tri::ch10::bench_settings(tri::ch10::SuiteSize::tiny);
  std::ostringstream progress;
  const tri::ch10::BenchReport report = tri::ch10::run_benchmark(
      measured, {}, settings, tri::describe_machine(tri::external_peer_status({})), progress);
  const tri::ch10::ReportFiles files = tri::ch10::render_report(report);
  CHECK(files.markdown.find("| `" + std::string(added().name) + "` | one_file_algorithm") !=
        std::string::npos);
  CHECK(files.csv.find(std::string(added().name) + ",") != std::string::npos);
}

}  // namespace
