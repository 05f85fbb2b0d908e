#include "chapters/10_speed_vs_error/user_path.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>

#include "chapters/10_speed_vs_error/report_csv.hpp"
#include "common/printable_text.hpp"
#include "common/temporary_folder.hpp"
#include "measure/number_format.hpp"
#include "measure/program_run.hpp"
#include "measure/scene_generators.hpp"
#include "measure/scene_text.hpp"

namespace tri::ch10 {
namespace {

// The words `key=value` of the output, by key (a later one replaces an earlier one).
std::map<std::string, std::string, std::less<>> values_of(std::string_view output) {
  std::map<std::string, std::string, std::less<>> values;
  std::istringstream words{std::string(output)};
  for (std::string word; words >> word;) {
    const auto equals = word.find('=');
    if (equals != std::string::npos) values[word.substr(0, equals)] = word.substr(equals + 1);
  }
  return values;
}

template <class Number>
Number number_of(const std::map<std::string, std::string, std::less<>>& values,
                 std::string_view key) {
  const auto found = values.find(key);
  if (found == values.end())
    throw std::runtime_error("raster --bench printed no " + std::string(key) + "=");
  Number number{};
  const std::string& text = found->second;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), number);
  if (error != std::errc() || end != text.data() + text.size()) {
    throw std::runtime_error("raster --bench printed " + std::string(key) + "=" +
                             printable_excerpt(text) + ", not a number");
  }
  return number;
}

std::string milliseconds(double seconds) {
  return format_number(seconds * 1e3, 3) + " ms";
}

// The run's first scene drawn by the algorithm: its row of the report.
const Measurement* first_row_of(const BenchReport& report, const TriangleAlgorithm& algorithm) {
  const auto row = std::find_if(report.rows.begin(), report.rows.end(), [&](const Measurement& m) {
    return m.algorithm == algorithm.name && m.chapter == algorithm.chapter;
  });
  return row == report.rows.end() ? nullptr : &*row;
}

}  // namespace

RasterBench parse_raster_bench(std::string_view output) {
  const auto values = values_of(output);
  return {.preparation_seconds = number_of<double>(values, "preparation_seconds"),
          .triangles = number_of<std::size_t>(values, "triangles"),
          .frames = number_of<long long>(values, "frames"),
          .frame_seconds = number_of<double>(values, "seconds")};
}

double UserPathComparison::ratio() const noexcept {
  return raster && report_seconds > 0 ? raster->frame_seconds / report_seconds : 0.0;
}

const TriangleAlgorithm* user_path_algorithm(std::span<const TriangleAlgorithm> algorithms) {
  if (const TriangleAlgorithm* followed = algorithm_with_role(algorithms, Role::cost_sweeps))
    return followed;
  return algorithms.empty() ? nullptr : &algorithms.front();
}

long long user_path_frames(double report_seconds, double budget_seconds) noexcept {
  if (!(report_seconds > 0)) return 21;
  return static_cast<long long>(
      std::clamp(std::round(budget_seconds / report_seconds), 21.0, 2001.0));
}

std::optional<UserPathComparison> measure_user_path(const BenchReport& report,
                                                    const TriangleAlgorithm& algorithm,
                                                    std::span<const SuiteScene> scenes,
                                                    const std::filesystem::path& raster_program,
                                                    double budget_seconds, std::ostream& progress) {
  const Measurement* row = first_row_of(report, algorithm);
  const auto suite = std::find_if(scenes.begin(), scenes.end(), [&](const SuiteScene& s) {
    return row != nullptr && s.name == row->scene && s.grid == row->grid;
  });
  if (suite == scenes.end()) return std::nullopt;
  UserPathComparison comparison;
  comparison.algorithm = row->algorithm;
  comparison.scene = row->scene;
  comparison.grid = row->grid;
  comparison.triangles = row->triangles;
  comparison.report_seconds = row->timing.seconds.median;
  const std::string file_name =
      suite->name + "_" + (suite->grid == "integer" ? "integer" : "256") + ".scene";
  const std::string frames =
      std::to_string(user_path_frames(comparison.report_seconds, budget_seconds));
  comparison.command =
      "raster --algo " + comparison.algorithm + " --scene " + file_name + " --bench " + frames;
  try {
    const TemporaryFolder folder("tri_user_path");
    const auto scene_file = folder / file_name;
    write_scene_file(scene_file, generate_scene(suite->recipe));
    const ProgramRun run = run_program({raster_program.string(), "--algo", comparison.algorithm,
                                        "--scene", scene_file.string(), "--bench", frames});
    if (!run.succeeded()) {
      throw std::runtime_error(
          printable_text(raster_program.string()) +
          (run.signal != 0 ? " was ended by signal " + std::to_string(run.signal)
                           : " failed (exit status " + std::to_string(run.exit_code) + ")") +
          ": " + printable_excerpt(run.errors));
    }
    comparison.raster = parse_raster_bench(run.output);
  } catch (const std::runtime_error& e) {
    comparison.problem = e.what();
  }
  progress << "user's path: " << comparison.command << ": "
           << (comparison.raster ? milliseconds(comparison.raster->frame_seconds) + " a frame, " +
                                       "the report's " + milliseconds(comparison.report_seconds)
                                 : "not measured: " + comparison.problem)
           << std::endl;  // flushed: the line is the progress
  return comparison;
}

std::string user_path_markdown(const std::optional<UserPathComparison>& comparison) {
  if (!comparison) return {};
  const UserPathComparison& c = *comparison;
  std::ostringstream md;
  md << "\n## The user's path\n\n";
  const std::string scene = "the run's " + c.scene + " scene (" + c.grid + " grid, " +
                            std::to_string(c.triangles) + " triangles, written as a scene file)";
  if (!c.raster) {
    md << "`raster` was not measured on " << scene << ": " << c.problem
       << ". Build the `raster` target, or name the program with `--raster FILE`.\n";
    return md.str();
  }
  md << "`" << c.command << "` on " << scene << ": " << milliseconds(c.raster->frame_seconds)
     << " a frame (median of " << c.raster->frames << "), beside the report's own "
     << milliseconds(c.report_seconds) << " for the same algorithm and triangles; `raster` / "
     << "report = " << format_number(c.ratio(), 3) << ". Preparing the scene once took `raster` "
     << milliseconds(c.raster->preparation_seconds) << ". Both are in `" << user_path_csv_file_name
     << "`.\n";
  return md.str();
}

std::string user_path_csv(const std::optional<UserPathComparison>& comparison) {
  constexpr std::string_view header =
      "algorithm,scene,grid,triangles,frames,report_median_s,raster_median_s,raster_over_report,"
      "raster_preparation_s,problem";
  std::span<const UserPathComparison> rows;
  if (comparison) rows = {&*comparison, 1};
  return csv_table(header, rows, [](const UserPathComparison& c) {
    // raster's numbers, or empty fields when it was not measured.
    const auto if_measured = [&c](auto text) { return c.raster ? text() : std::string(); };
    return std::tuple(c.algorithm, c.scene, c.grid, c.triangles,
                      if_measured([&c] { return std::to_string(c.raster->frames); }),
                      format_number(c.report_seconds, 6),
                      if_measured([&c] { return format_number(c.raster->frame_seconds, 6); }),
                      if_measured([&c] { return format_number(c.ratio(), 6); }),
                      if_measured([&c] { return format_number(c.raster->preparation_seconds, 6); }),
                      quoted_text(c.problem));
  });
}

}  // namespace tri::ch10
