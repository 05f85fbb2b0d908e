// The user's path in the report: `raster --bench` run as a program on one of the run's scenes,
// beside the report's own time. These tests check what is read and written, never a speed.
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "chapters/10_speed_vs_error/user_path.hpp"
#include "measure/number_format.hpp"
#include "measure/registry.hpp"
#include "tests/support/text.hpp"

namespace {

using tri::ch10::UserPathComparison;
using tri::testing::fields_of;
using tri::testing::lines_of;

// A tiny run of the algorithm the comparison follows, and the comparison through raster_program.
struct TinyUserPath {
  tri::ch10::BenchSettings settings = tri::ch10::bench_settings(tri::ch10::SuiteSize::tiny);
  std::vector<tri::TriangleAlgorithm> algorithms;
  tri::ch10::BenchReport report;
  std::ostringstream progress;
  std::optional<UserPathComparison> comparison;

  explicit TinyUserPath(const std::string& raster_program) {
    const auto all = tri::registered_algorithms();
    algorithms.push_back(*tri::ch10::user_path_algorithm(all));
    std::ostringstream run_progress;
    report = tri::ch10::run_benchmark(algorithms, {}, settings, {}, run_progress);
    comparison = tri::ch10::measure_user_path(report, algorithms.front(), settings.scenes,
                                              raster_program, 0.001, progress);
  }
};

}  // namespace

TEST_CASE("parse_raster_bench reads raster's two --bench lines and names a missing value",
          "[10_speed_vs_error][user_path]") {
  const std::string printed =
      "preparation_seconds=0.00125\n"
      "triangles=4000 frames=21 seconds=0.000375 min_seconds=0.00025 max_seconds=0.0005 "
      "tris_per_s=1.06667e+07 mpix_per_s=12.5\n";
  const tri::ch10::RasterBench bench = tri::ch10::parse_raster_bench(printed);
  CHECK(bench.preparation_seconds == 0.00125);
  CHECK(bench.triangles == 4000);
  CHECK(bench.frames == 21);
  CHECK(bench.frame_seconds == 0.000375);  // the median, not min_seconds or max_seconds
  CHECK_THROWS_WITH(tri::ch10::parse_raster_bench("triangles=1 frames=2 min_seconds=0.5\n"),
                    Catch::Contains("no preparation_seconds="));
  CHECK_THROWS_WITH(
      tri::ch10::parse_raster_bench("preparation_seconds=1\ntriangles=1 frames=2 min_seconds=3\n"),
      Catch::Contains("no seconds="));
  CHECK_THROWS_WITH(tri::ch10::parse_raster_bench(
                        "preparation_seconds=1\ntriangles=1 frames=2 seconds=fast min_seconds=3\n"),
                    Catch::Contains("seconds=fast, not a number"));
}

TEST_CASE("user_path_algorithm follows the sweeps' algorithm, else the first selected",
          "[10_speed_vs_error][user_path]") {
  const auto all = tri::registered_algorithms();
  const tri::TriangleAlgorithm* followed = tri::ch10::user_path_algorithm(all);
  REQUIRE(followed != nullptr);
  CHECK(followed->role == tri::Role::cost_sweeps);
  std::vector<tri::TriangleAlgorithm> without;
  for (const auto& a : all)
    if (a.role != tri::Role::cost_sweeps) without.push_back(a);
  CHECK(tri::ch10::user_path_algorithm(without)->name == without.front().name);
  CHECK(tri::ch10::user_path_algorithm({}) == nullptr);
}

TEST_CASE("The user's path runs raster --bench on the run's first scene beside the report's time",
          "[10_speed_vs_error][user_path]") {
  const TinyUserPath run(RASTER_PROGRAM);
  REQUIRE(run.comparison);
  const UserPathComparison& c = *run.comparison;
  INFO(c.problem);
  REQUIRE(c.raster);
  CHECK(c.problem.empty());
  const auto& first = run.report.rows.front();
  CHECK(c.algorithm == run.algorithms.front().name);
  CHECK(c.scene == first.scene);
  CHECK(c.grid == first.grid);
  CHECK(c.report_seconds == first.timing.seconds.median);
  // raster read the scene file whole and drew the frames asked for.
  CHECK(c.raster->triangles == first.triangles);
  CHECK(c.raster->frames == tri::ch10::user_path_frames(c.report_seconds, 0.001));
  CHECK(c.command == "raster --algo " + c.algorithm + " --scene " + c.scene + "_integer.scene" +
                         " --bench " + std::to_string(c.raster->frames));
  CHECK(c.raster->frame_seconds > 0);
  CHECK(c.raster->preparation_seconds > 0);
  CHECK(c.ratio() == c.raster->frame_seconds / c.report_seconds);
  CHECK_THAT(run.progress.str(), Catch::StartsWith("user's path: " + c.command + ": "));

  const std::string markdown = tri::ch10::user_path_markdown(run.comparison);
  CHECK_THAT(markdown, Catch::Contains("## The user's path"));
  CHECK_THAT(markdown, Catch::Contains("`" + c.command + "`"));
  CHECK_THAT(markdown,
             Catch::Contains(tri::format_number(c.raster->frame_seconds * 1e3, 3) + " ms a frame"));
  CHECK_THAT(markdown,
             Catch::Contains("report's own " + tri::format_number(c.report_seconds * 1e3, 3)));
  CHECK_THAT(markdown, Catch::Contains("report = " + tri::format_number(c.ratio(), 3) + "."));

  const auto lines = lines_of(tri::ch10::user_path_csv(run.comparison));
  REQUIRE(lines.size() == 2);
  const auto header = fields_of(lines[0]);
  const auto fields = fields_of(lines[1]);
  REQUIRE(fields.size() == header.size());
  CHECK(header[5] == "report_median_s");
  CHECK(header[6] == "raster_median_s");
  CHECK(header[7] == "raster_over_report");
  CHECK(fields[0] == c.algorithm);
  CHECK(std::stoull(fields[3]) == c.raster->triangles);
  CHECK(std::stoll(fields[4]) == c.raster->frames);
  const double report_seconds = std::stod(fields[5]), raster_seconds = std::stod(fields[6]);
  CHECK(raster_seconds == Approx(c.raster->frame_seconds).epsilon(1e-5));
  CHECK(report_seconds == Approx(c.report_seconds).epsilon(1e-5));
  CHECK(std::stod(fields[7]) == Approx(raster_seconds / report_seconds).epsilon(1e-4));
  CHECK(fields.back() == "\"\"");
}

TEST_CASE("Without the raster program the report says so instead of a time",
          "[10_speed_vs_error][user_path]") {
  const TinyUserPath run("/nonexistent/raster");
  REQUIRE(run.comparison);
  const UserPathComparison& c = *run.comparison;
  CHECK_FALSE(c.raster);
  CHECK(c.ratio() == 0);
  CHECK_THAT(c.problem, Catch::Contains("cannot start /nonexistent/raster: No such file"));
  CHECK_THAT(tri::ch10::user_path_markdown(run.comparison),
             Catch::Contains("`raster` was not measured on the run's " + c.scene + " scene") &&
                 Catch::Contains(c.problem) && Catch::Contains("--raster FILE"));
  const auto lines = lines_of(tri::ch10::user_path_csv(run.comparison));
  REQUIRE(lines.size() == 2);
  CHECK_THAT(lines[1], Catch::EndsWith(",,,,\"" + c.problem + "\""));
  CHECK_THAT(run.progress.str(), Catch::Contains("not measured: " + c.problem));
}
