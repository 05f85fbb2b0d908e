// The report code on the tiny setting: three algorithms, 32x32 scenes, one run per sample. These
// tests check the outputs' form and the error numbers, never a speed.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "chapters/10_speed_vs_error/blend2d_shapes.hpp"
#include "chapters/10_speed_vs_error/coverage_report.hpp"
#include "chapters/10_speed_vs_error/plot_svg.hpp"
#include "chapters/10_speed_vs_error/report.hpp"
#include "chapters/10_speed_vs_error/report_csv.hpp"
#include "chapters/10_speed_vs_error/report_markdown.hpp"
#include "chapters/10_speed_vs_error/snapshot.hpp"
#include "chapters/10_speed_vs_error/summary.hpp"
#include "measure/error_metrics.hpp"
#include "measure/peers/external_peers.hpp"
#include "measure/registry.hpp"
#include "measure/render_scene.hpp"
#include "tests/support/text.hpp"

using tri::ch10::BenchReport;
using tri::ch10::Measurement;
using tri::testing::fields_of;
using tri::testing::lines_of;
using tri::testing::occurrences;

namespace {

// A folder name of its own under the temporary folder, so two builds testing at once never share
// it.
std::filesystem::path unique_temporary_folder(const std::string& stem) {
  return std::filesystem::temp_directory_path() /
         (stem + "_" + std::to_string(std::random_device{}()));
}

const std::vector<std::string> tiny_algorithms{"edge_function", "fixed_point_0", "fixed_point_8"};

std::vector<tri::TriangleAlgorithm> chosen_algorithms() {
  const auto all = tri::registered_algorithms();
  std::vector<tri::TriangleAlgorithm> chosen;
  for (const std::string& name : tiny_algorithms) {
    const tri::TriangleAlgorithm* algorithm = tri::find_named(all, name);
    REQUIRE(algorithm != nullptr);
    chosen.push_back(*algorithm);
  }
  return chosen;
}

const std::vector<std::string> tiny_area_algorithms{"area_cells",         "samples_grid_1x1",
                                                    "samples_grid_2x2",   "samples_grid_4x4",
                                                    "samples_standard_4", "samples_standard_16"};

std::vector<tri::ch09::AreaAlgorithm> chosen_area_algorithms() {
  const auto all = tri::registered_area_algorithms();
  std::vector<tri::ch09::AreaAlgorithm> chosen;
  for (const std::string& name : tiny_area_algorithms) {
    const auto* algorithm = tri::find_named(all, name);
    REQUIRE(algorithm != nullptr);
    chosen.push_back(*algorithm);
  }
  return chosen;
}

// One tiny run shared by the tests (it takes well under a second).
struct TinyRun {
  tri::ch10::BenchSettings settings = tri::ch10::bench_settings(tri::ch10::SuiteSize::tiny);
  std::ostringstream progress;
  std::vector<tri::ExternalPeer> peers = tri::external_peers();
  BenchReport report;
  tri::ch10::CoverageReport coverage;
  std::ostringstream scaling_progress;  // the sweeps' own lines, apart from the two parts'
  std::vector<tri::ch10::ScalingPoint> scaling;
  std::ostringstream shapes_progress;  // Blend2D's shapes, lines of their own
  std::vector<tri::ch10::ShapeRate> shapes;
  tri::ch10::ReportFiles files;
  TinyRun() {
    report =
        tri::ch10::run_benchmark(chosen_algorithms(), peers, settings,
                                 tri::describe_machine(tri::external_peer_status(peers)), progress);
    coverage.rows =
        tri::ch10::run_coverage_benchmark(chosen_area_algorithms(), {}, settings, progress);
    coverage.peer_status = "none measured";
    const auto all = tri::registered_algorithms();
    scaling = tri::ch10::run_scaling(tri::ch10::scaling_drawers(all, peers),
                                     tri::ch10::scaling_settings(tri::ch10::SuiteSize::tiny),
                                     scaling_progress);
    shapes = tri::ch10::run_blend2d_shapes(
        chosen_algorithms(), peers, chosen_area_algorithms(), tri::coverage_peers(),
        tri::ch10::blend2d_shapes_settings(tri::ch10::SuiteSize::tiny), shapes_progress);
    files = tri::ch10::render_report(report, coverage, scaling, shapes);
  }
};

const TinyRun& tiny_run() {
  static const TinyRun run;
  return run;
}

// Every row name of the tiny run, in the report's order: the algorithms, then this build's peers.
std::vector<std::string> measured_names() {
  std::vector<std::string> names = tiny_algorithms;
  for (const tri::ExternalPeer& peer : tiny_run().peers) names.emplace_back(peer.name);
  return names;
}

// Checks that every element is closed in order: "<a>" ... "</a>", or "<a/>". Returns the first
// problem, or "" for a balanced document.
std::string unbalanced_tag(const std::string& svg) {
  std::vector<std::string> open;
  for (auto at = svg.find('<'); at != std::string::npos; at = svg.find('<', at + 1)) {
    const auto end = svg.find('>', at);
    if (end == std::string::npos) return "a tag is never closed with '>'";
    const std::string tag = svg.substr(at + 1, end - at - 1);
    if (tag.empty()) return "an empty tag";
    if (tag.front() == '/') {
      if (open.empty() || open.back() != tag.substr(1)) return "unexpected </" + tag.substr(1);
      open.pop_back();
    } else if (tag.back() != '/') {
      open.push_back(tag.substr(0, tag.find_first_of(" \n")));
    }
    at = end;
  }
  return open.empty() ? "" : "<" + open.back() + "> is never closed";
}

// A JSON value parsed back from a file the report wrote: enough of JSON for bl_bench's layout
// (objects, arrays, strings without escapes beyond \" and \\, numbers, null). Throws on
// anything else, and on text after the value.
struct Json {
  enum class Kind { null, number, string, array, object } kind = Kind::null;
  double number = 0;
  std::string text;
  std::vector<Json> items;
  // An object's keys and values side by side: a pair would need Json complete (Clang's check).
  std::vector<std::string> keys;
  std::vector<Json> values;

  const Json& at(const std::string& key) const {
    for (std::size_t i = 0; i < keys.size(); ++i) {
      if (keys[i] == key) return values[i];
    }
    throw std::runtime_error("no key " + key);
  }
};

class JsonParser {
 public:
  explicit JsonParser(const std::string& text) : text_(text) {}
  Json document() {
    Json value = parse();
    skip_space();
    if (at_ != text_.size()) throw std::runtime_error("text after the value");
    return value;
  }

 private:
  void skip_space() {
    while (at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_]))) ++at_;
  }
  void expect(char c) {
    skip_space();
    if (at_ >= text_.size() || text_[at_] != c) throw std::runtime_error(std::string("no ") + c);
    ++at_;
  }
  bool next_is(char c) {
    skip_space();
    return at_ < text_.size() && text_[at_] == c;
  }
  std::string string() {
    expect('"');
    std::string out;
    while (at_ < text_.size() && text_[at_] != '"') {
      if (text_[at_] == '\\') ++at_;
      out += text_.at(at_++);
    }
    expect('"');
    return out;
  }
  Json parse() {
    Json value;
    if (next_is('{')) {
      value.kind = Json::Kind::object;
      expect('{');
      while (!next_is('}')) {
        if (!value.keys.empty()) expect(',');
        std::string key = string();
        expect(':');
        value.keys.push_back(std::move(key));
        value.values.push_back(parse());
      }
      expect('}');
    } else if (next_is('[')) {
      value.kind = Json::Kind::array;
      expect('[');
      while (!next_is(']')) {
        if (!value.items.empty()) expect(',');
        value.items.push_back(parse());
      }
      expect(']');
    } else if (next_is('"')) {
      value.kind = Json::Kind::string;
      value.text = string();
    } else if (text_.compare(at_, 4, "null") == 0) {
      at_ += 4;
    } else {
      std::size_t used = 0;
      value.kind = Json::Kind::number;
      value.number = std::stod(text_.substr(at_, 32), &used);
      at_ += used;
    }
    return value;
  }

  const std::string& text_;
  std::size_t at_ = 0;
};

}  // namespace

TEST_CASE("The tiny run measures every algorithm on every scene once, with a progress line each",
          "[10_speed_vs_error][report]") {
  const TinyRun& run = tiny_run();
  REQUIRE(run.report.rows.size() == measured_names().size() * run.settings.scenes.size());
  std::map<std::tuple<std::string, std::string, std::string>, int> seen;
  for (const Measurement& m : run.report.rows) ++seen[{m.algorithm, m.scene, m.grid}];
  CHECK(seen.size() == run.report.rows.size());
  CHECK(lines_of(run.progress.str()).size() == run.report.rows.size() + run.coverage.rows.size());
  CHECK(run.report.width == 32);
  CHECK(run.report.height == 32);
}

TEST_CASE("Each measurement is timed with one run per sample, its median within its spread",
          "[10_speed_vs_error][step2][report]") {
  for (const Measurement& m : tiny_run().report.rows) {
    CHECK(m.timing.repetitions == 1);
    CHECK(m.timing.samples == 1);
    CHECK(m.timing.seconds.min <= m.timing.seconds.median);
    CHECK(m.timing.seconds.median <= m.timing.seconds.max);
    CHECK(m.fill_ceiling_mpix_per_s >= 0);
  }
}

TEST_CASE("The error numbers are measure_error's on the same scene",
          "[10_speed_vs_error][step4][report]") {
  const auto algorithms = chosen_algorithms();
  for (const Measurement& m : tiny_run().report.rows) {
    const auto suite = std::find_if(
        tiny_run().settings.scenes.begin(), tiny_run().settings.scenes.end(),
        [&](const tri::SuiteScene& s) { return s.name == m.scene && s.grid == m.grid; });
    REQUIRE(suite != tiny_run().settings.scenes.end());
    const tri::Scene scene = tri::generate_scene(suite->recipe);
    CAPTURE(m.algorithm, m.scene, m.grid);
    const auto it =
        std::find_if(algorithms.begin(), algorithms.end(),
                     [&](const tri::TriangleAlgorithm& a) { return a.name == m.algorithm; });
    if (it == algorithms.end()) {
      // An external peer (its own measure_error is tested with it): the same oracle pixels.
      CHECK(m.chapter == "external");
      CHECK(m.error.covered == tri::measure_error(algorithms.back(), scene).covered);
      CHECK(m.written_pixels == m.error.covered - m.error.missed + m.error.extra);
      continue;
    }
    const tri::ErrorReport expected = tri::measure_error(*it, scene);
    CHECK(m.error_triangles == m.triangles);
    CHECK(m.error.covered == expected.covered);
    CHECK(m.error.missed == expected.missed);
    CHECK(m.error.extra == expected.extra);
    CHECK(m.error.gaps == expected.gaps);
    CHECK(m.error.overdraw == expected.overdraw);
    CHECK(m.error.order_dependent == expected.order_dependent);
    CHECK(m.error.outside_writes == 0);
    // Pixels written, counted in their own draw, agree with the oracle's count and the error.
    CHECK(m.written_pixels == m.error.covered - m.error.missed + m.error.extra);
  }
}

TEST_CASE("The top-left algorithm is exact on every scene and the 0-bit one is not",
          "[10_speed_vs_error][step4][report]") {
  std::uint64_t wrong_0 = 0;
  for (const Measurement& m : tiny_run().report.rows) {
    if (m.algorithm == "fixed_point_8") CHECK(m.error.exact());
    if (m.algorithm == "fixed_point_0") wrong_0 += m.error.missed + m.error.extra;
  }
  CHECK(wrong_0 > 0);
}

TEST_CASE("The CSV has its header and the same number of fields on every row",
          "[10_speed_vs_error][step5][report]") {
  const TinyRun& run = tiny_run();
  const auto lines = lines_of(run.files.csv);
  REQUIRE(lines.size() == 1 + run.report.rows.size());
  const auto columns = tri::ch10::csv_columns();
  const auto header = fields_of(lines[0]);
  REQUIRE(header.size() == columns.size());
  for (std::size_t i = 0; i < columns.size(); ++i) CHECK(header[i] == columns[i]);
  // These columns must be there, whatever else the header holds.
  for (const std::string& name :
       fields_of("algorithm,chapter,rule,scene,grid,triangles,covered_pixels,median_s,min_s,max_s,"
                 "tris_per_s,mpix_per_s,fill_ceiling_mpix_per_s,ratio_to_ceiling,missed,extra,"
                 "gaps,overdraw,order_dependent,error_rate")) {
    CAPTURE(name);
    CHECK(std::find(header.begin(), header.end(), name) != header.end());
  }
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const auto fields = fields_of(lines[i]);
    CHECK(fields.size() == columns.size());
    const Measurement& m = run.report.rows[i - 1];
    CHECK(fields[0] == m.algorithm);
    CHECK(fields[4] == m.scene);
    CHECK(fields[5] == m.grid);
    CHECK(fields[21] == std::to_string(m.error.missed));
    CHECK(fields[22] == std::to_string(m.error.extra));
  }
}

TEST_CASE("The Markdown report has the machine and a table row per algorithm",
          "[10_speed_vs_error][step5][report]") {
  const TinyRun& run = tiny_run();
  const std::string& md = run.files.markdown;
  CHECK(md.starts_with("# "));
  CHECK(md.find("| nproc | ") != std::string::npos);
  CHECK(md.find("| CPU | " + run.report.machine.cpu_model + " |") != std::string::npos);
  CHECK(md.find("| compiler | ") != std::string::npos);
  CHECK(md.find("| build type | ") != std::string::npos);
  const std::string suite_canvas =
      std::to_string(run.report.width) + "×" + std::to_string(run.report.height);
  CHECK(md.find("| write ceiling, 1 thread, " + suite_canvas + " | ") != std::string::npos);
  CHECK(md.find("| write ceiling, 1 thread, 64×64 | ") != std::string::npos);  // the reference
  REQUIRE(run.report.reference_ceilings.size() == 1);
  CHECK(run.report.reference_ceilings[0].side == 64);
  CHECK(run.report.reference_ceilings[0].one_thread.mpix_per_s() > 0);
  CHECK(md.find("| External peers | " + run.report.machine.external_peers + " |") !=
        std::string::npos);
  CHECK(occurrences(md, "| External peers |") == 1);  // one row each, in one table
  CHECK(occurrences(md, "| write ceiling, ") == 3);
  const auto names = measured_names();
  const auto lines = lines_of(md);
  const auto header = std::find_if(lines.begin(), lines.end(), [](const std::string& l) {
    return l.starts_with("| algorithm |");
  });
  REQUIRE(header != lines.end());
  const std::size_t columns = occurrences(*header, "|");
  std::size_t rows = 0;
  for (auto it = header + 2; it != lines.end() && it->starts_with("| `"); ++it, ++rows) {
    CHECK(occurrences(*it, "|") == columns);
    CHECK(it->find("`" + names[rows] + "`") != std::string::npos);
  }
  CHECK(rows == names.size());
  CHECK(md.find("| `fixed_point_8` | 07_exact_coverage | top-left |") != std::string::npos);
}

TEST_CASE("The SVG is one balanced document with a circle per algorithm",
          "[10_speed_vs_error][step5][report]") {
  const std::string& svg = tiny_run().files.svg;
  CHECK(svg.starts_with("<svg "));
  CHECK(unbalanced_tag(svg).empty());
  CHECK(occurrences(svg, "<svg") == 1);
  CHECK(occurrences(svg, "<circle ") == measured_names().size());
  for (const std::string& name : measured_names()) {
    CAPTURE(name);
    CHECK((svg.find(">" + name + "</text>") != std::string::npos ||
           svg.find(">" + name + " (threads)</text>") != std::string::npos));
  }
  // fixed_point_0 and fixed_point_8 are one family: one line joins them.
  CHECK(occurrences(svg, "<polyline ") == 1);
  CHECK(svg.find(">exact</text>") != std::string::npos);
  CHECK(svg.find("write ceiling (memset, vector stores), 1 thread: ") != std::string::npos);
}

TEST_CASE("The exact algorithm is drawn on the exact floor of the plot",
          "[10_speed_vs_error][step5][report]") {
  const auto summaries = tri::ch10::summarize(tiny_run().report.rows);
  const tri::ch10::PlotLayout layout;
  const tri::ErrorAxis axis = tri::ch10::error_axis_for(summaries, layout);
  for (const auto& s : summaries) {
    CAPTURE(s.algorithm);
    if (s.algorithm == "fixed_point_8") CHECK(axis.position(s.error_rate()) == axis.zero_position);
    if (s.algorithm == "fixed_point_0") CHECK(axis.position(s.error_rate()) > axis.zero_position);
    CHECK(axis.position(s.error_rate()) >= layout.left);
    CHECK(axis.position(s.error_rate()) <= layout.right);
  }
}

TEST_CASE("Text in the SVG is escaped", "[10_speed_vs_error][step5][report]") {
  CHECK(tri::escape_xml("a<b & \"c\">") == "a&lt;b &amp; &quot;c&quot;&gt;");
}

TEST_CASE("Rates are written with a k, M or G suffix", "[10_speed_vs_error][step5][report]") {
  CHECK(tri::human_rate(0) == "–");
  CHECK(tri::human_rate(950) == "950");
  CHECK(tri::human_rate(12'345) == "12.3 k");
  CHECK(tri::human_rate(4'560'000) == "4.56 M");
  CHECK(tri::human_rate(2e9) == "2 G");
}

TEST_CASE("Table speeds are whole numbers from 100 Mpix/s up",
          "[10_speed_vs_error][step5][report]") {
  CHECK(tri::format_mpix(1559.6) == "1560");
  CHECK(tri::format_mpix(100.0) == "100");
  CHECK(tri::format_mpix(22.94) == "22.9");
  CHECK(tri::format_mpix(0.0) == "0");
}

TEST_CASE("Error rates are exact at zero, else three significant digits",
          "[10_speed_vs_error][step5][report]") {
  CHECK(tri::format_error_rate(0) == "0 (exact)");
  CHECK(tri::format_error_rate(0.0022419) == "0.00224");
  CHECK(tri::format_error_rate(5.41e-06) == "5.41e-06");
}

TEST_CASE("save_report writes the eleven files the run rendered", "[10_speed_vs_error][report]") {
  const auto folder = unique_temporary_folder("tri_ch09_report_test");
  std::filesystem::remove_all(folder);
  std::ostringstream log;
  tri::ch10::save_report(folder, tiny_run().report, tiny_run().coverage, tiny_run().scaling,
                         tiny_run().shapes, std::nullopt, log);
  const auto read = [&](const char* name) {
    std::ifstream in(folder / name, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  CHECK(read(tri::ch10::csv_file_name) == tiny_run().files.csv);
  CHECK(read(tri::ch10::markdown_file_name) == tiny_run().files.markdown);
  CHECK(read(tri::ch10::svg_file_name) == tiny_run().files.svg);
  CHECK(read(tri::ch10::coverage_csv_file_name) == tiny_run().files.coverage_csv);
  CHECK(read(tri::ch10::coverage_svg_file_name) == tiny_run().files.coverage_svg);
  CHECK(read(tri::ch10::scaling_csv_file_name) == tiny_run().files.scaling_csv);
  CHECK(read(tri::ch10::scaling_triangles_svg_file_name) == tiny_run().files.scaling_triangles_svg);
  CHECK(read(tri::ch10::scaling_canvas_svg_file_name) == tiny_run().files.scaling_canvas_svg);
  CHECK(read(tri::ch10::blend2d_shapes_csv_file_name) == tiny_run().files.blend2d_shapes_csv);
  CHECK(read(tri::ch10::blend2d_shapes_json_file_name) == tiny_run().files.blend2d_shapes_json);
  CHECK(read(tri::ch10::user_path_csv_file_name) == tiny_run().files.user_path_csv);
  CHECK_THAT(tiny_run().files.markdown, Catch::Contains("## How cost grows"));
  CHECK(lines_of(log.str()).size() == 11);
  std::filesystem::remove_all(folder);
}

TEST_CASE("save_report writes the set whole or not at all: a failing file keeps the earlier set",
          "[10_speed_vs_error][report]") {
  const auto folder = unique_temporary_folder("tri_ch09_report_set_test");
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder / tri::ch10::svg_file_name);  // cannot be replaced
  std::ofstream(folder / tri::ch10::csv_file_name) << "earlier csv";
  std::ostringstream log;
  CHECK_THROWS_WITH(
      tri::ch10::save_report(folder, tiny_run().report, tiny_run().coverage, tiny_run().scaling,
                             tiny_run().shapes, std::nullopt, log),
      Catch::Contains("Is a directory"));
  std::ifstream csv(folder / tri::ch10::csv_file_name);
  CHECK(std::string(std::istreambuf_iterator<char>(csv), {}) == "earlier csv");
  CHECK_FALSE(std::filesystem::exists(folder / tri::ch10::markdown_file_name));
  CHECK(std::distance(std::filesystem::directory_iterator(folder), {}) == 2);
  CHECK(log.str().empty());
  std::filesystem::remove_all(folder);
}

TEST_CASE("A threaded algorithm is held to the faster ceiling, any other to one thread's",
          "[10_speed_vs_error][step3][report]") {
  tri::TriangleAlgorithm threaded = chosen_algorithms().front();
  threaded.threaded = true;
  // Each ceiling is the faster of its two fills (memset, vector stores).
  const tri::ch10::FillCeilings ceilings{{100.0, 60.0}, {20.0, 300.0}, 2};
  CHECK(ceilings.single_thread_mpix_per_s() == 100.0);
  CHECK(ceilings.threaded_mpix_per_s() == 300.0);
  CHECK(tri::ch10::FillCeilings{{50.0, 100.0}, {40.0, 30.0}, 2}.threaded_mpix_per_s() == 100.0);
  const auto prepared = tri::prepare_scene(tiny_run().settings.scenes.front(), 0);
  const auto plan = tiny_run().settings.timing;
  CHECK(tri::ch10::measure(threaded, prepared, plan, ceilings).fill_ceiling_mpix_per_s == 300.0);
  CHECK(tri::ch10::measure(chosen_algorithms().front(), prepared, plan, ceilings)
            .fill_ceiling_mpix_per_s == 100.0);
}

TEST_CASE("The error scene keeps the first triangles when the error is measured on a subset",
          "[10_speed_vs_error][step4][report]") {
  const tri::SuiteScene& suite = tiny_run().settings.scenes.front();
  const auto whole = tri::prepare_scene(suite, 0);
  const auto part = tri::prepare_scene(suite, 5);
  REQUIRE(whole.triangles.size() > 5);
  CHECK(part.triangles.size() == whole.triangles.size());  // the timed scene is never cut
  const auto kept = tri::scene_triangles(part.error_scene);
  REQUIRE(kept.size() == 5);
  for (std::size_t i = 0; i < kept.size(); ++i) {
    CHECK(kept[i].vertices == whole.triangles[i].vertices);
  }
  CHECK(tri::count_triangles(whole.error_scene) == whole.triangles.size());
}

TEST_CASE("A threaded algorithm is labelled as such and gets its own ceiling line",
          "[10_speed_vs_error][step5][report]") {
  BenchReport report = tiny_run().report;
  report.ceilings = {{100.0, 0.0}, {0.0, 250.0}, 2};
  auto summaries = tri::ch10::summarize(report.rows);
  summaries[0].threaded = true;
  const std::string svg = tri::ch10::to_svg(report, summaries);
  CHECK(unbalanced_tag(svg).empty());
  CHECK(occurrences(svg, "<circle ") == summaries.size());
  CHECK(svg.find(">" + summaries[0].algorithm + " (threads)</text>") != std::string::npos);
  CHECK(svg.find("write ceiling (memset, vector stores), 1 thread: 100 Mpix/s") !=
        std::string::npos);
  CHECK(svg.find("write ceiling, 2 threads: 250 Mpix/s") != std::string::npos);
}

TEST_CASE("The coverage part measures every chosen coverage algorithm on every scene",
          "[10_speed_vs_error][coverage]") {
  const auto& rows = tiny_run().coverage.rows;
  REQUIRE(rows.size() == tiny_area_algorithms.size() * tiny_run().settings.scenes.size());
  for (const tri::ch10::CoverageMeasurement& m : rows) {
    INFO(m.algorithm << " on " << m.scene << " " << m.grid);
    CHECK(m.rule == "area");
    CHECK(m.error.triangles > 0);
    CHECK(m.error.rejected == 0);
    CHECK(m.touched_pixels > 0);
    if (m.algorithm == "area_cells") {
      CHECK(m.error.max_units <= 1);  // the exact area, to a float's rounding
      CHECK(m.error.composed_off_pixels == 0);
    } else {
      CHECK(m.error.mean > 0);  // sampling is an estimate
    }
  }
  CHECK(tiny_run().files.coverage_csv.starts_with("algorithm,chapter,rule,samples,scene,grid,"));
  CHECK(lines_of(tiny_run().files.coverage_csv).size() == rows.size() + 1);
}

TEST_CASE("A coverage summary weighs the error by pixels and compares the time with chapter 08's",
          "[10_speed_vs_error][coverage]") {
  const auto row = [](std::string name, std::string scene, double seconds, double mean,
                      std::uint64_t pixels) {
    tri::ch10::CoverageMeasurement m;
    m.algorithm = std::move(name);
    m.chapter = "09_anti_aliasing";
    m.rule = "area";
    m.scene = std::move(scene);
    m.grid = "integer";
    m.triangles = 100;
    m.timing.seconds.median = seconds;
    m.error.mean = mean;
    m.error.pixels = pixels;
    m.error.max = 2 * mean;
    return m;
  };
  const std::vector<tri::ch10::CoverageMeasurement> rows = {row("a", "tiny", 0.004, 0.1, 100),
                                                            row("a", "mesh", 0.001, 0.4, 300)};
  std::vector<Measurement> triangle_rows(3);
  for (auto& m : triangle_rows) m.chapter = "08_fast_exact";
  triangle_rows[0].scene = "tiny", triangle_rows[0].timing.seconds.median = 0.002;
  triangle_rows[1].scene = "tiny", triangle_rows[1].timing.seconds.median = 0.001;
  triangle_rows[2].scene = "mesh", triangle_rows[2].timing.seconds.median = 0.001;
  for (auto& m : triangle_rows) m.grid = "integer";
  const auto summaries = tri::ch10::summarize_coverage(rows, triangle_rows);
  REQUIRE(summaries.size() == 1);
  CHECK(summaries[0].scenes == 2);
  CHECK(summaries[0].mean_error == Approx((0.1 * 100 + 0.4 * 300) / 400));
  CHECK(summaries[0].max_error == Approx(0.8));
  // Against the fastest chapter 08 time of each scene: 4x on tiny, 1x on mesh, geometric mean 2x.
  CHECK(summaries[0].cost_vs_fastest == Approx(2.0));
  CHECK(summaries[0].tris_per_s == Approx(std::sqrt(25'000.0 * 100'000.0)));
}

TEST_CASE("The coverage section and plot show every summary, the grids' slope and the 1/n guide",
          "[10_speed_vs_error][coverage]") {
  const auto summaries =
      tri::ch10::summarize_coverage(tiny_run().coverage.rows, tiny_run().report.rows);
  REQUIRE(summaries.size() == tiny_area_algorithms.size());
  const std::string& md = tiny_run().files.markdown;
  REQUIRE(md.find("## Coverage: rule area") != std::string::npos);
  for (const std::string& name : tiny_area_algorithms) {
    CHECK(md.find("| `" + name + "` | 09_anti_aliasing |") != std::string::npos);
  }
  CHECK(md.find("On the regular grids the mean error falls as n^") != std::string::npos);
  const std::string& svg = tiny_run().files.coverage_svg;
  CHECK(unbalanced_tag(svg).empty());
  // One circle per algorithm and four in the legend; the grid and standard curves and the guide.
  CHECK(occurrences(svg, "<circle ") == summaries.size() + 4);
  CHECK(occurrences(svg, "<polyline ") == 3);
  CHECK(svg.find("error ∝ 1/n, cost ∝ n² (guide)") != std::string::npos);
  CHECK(tri::ch10::coverage_markdown({}, {}, "none").empty());
}

TEST_CASE("The coverage plot's legend starts right of the labels of the points at the exact floor",
          "[10_speed_vs_error][coverage]") {
  const std::string& svg = tiny_run().files.coverage_svg;
  const std::regex legend_box(R"re(<rect x="([0-9.]+)" y="[0-9.]+" width="290")re");
  std::smatch legend;
  const bool found = std::regex_search(svg, legend, legend_box);
  REQUIRE(found);
  const double legend_left = std::stod(legend[1].str());
  // Labels at the floor start 8 pixels right of it, about 6.4 pixels per character.
  const std::regex floor_label(R"re(<text x="([0-9.]+)" y="[0-9.]+">(area_cells[a-z_, ]*)<)re");
  int labels = 0;
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), floor_label);
       it != std::sregex_iterator(); ++it, ++labels) {
    const double right = std::stod((*it)[1].str()) + 6.4 * static_cast<double>((*it)[2].length());
    CHECK(right < legend_left);
  }
  CHECK(labels >= 1);
}

TEST_CASE("Every line of the coverage CSV has as many fields as its header, peers included",
          "[10_speed_vs_error][coverage]") {
  for (const tri::CoveragePeer& peer : tri::coverage_peers()) {
    INFO(peer.name);
    CHECK(peer.name.find(',') == std::string::npos);
  }
  const auto lines = lines_of(tiny_run().files.coverage_csv);
  REQUIRE(lines.size() > 1);
  for (const std::string& line : lines) CHECK(occurrences(line, ",") == occurrences(lines[0], ","));
}

TEST_CASE("The snapshot names the run's header, then one KEY,VALUE line per quoted number",
          "[10_speed_vs_error][snapshot]") {
  const TinyRun& run = tiny_run();
  const std::string text = tri::ch10::snapshot_text(
      run.report, run.coverage, {"0123abc", "2026-01-02", "pixman 1.2", "shared"});
  const auto lines = lines_of(text);
  const auto summaries = tri::ch10::summarize(run.report.rows);
  const auto coverage = tri::ch10::summarize_coverage(run.coverage.rows, run.report.rows);
  REQUIRE(lines.size() ==
          8 + 8 * summaries.size() + 4 * run.report.rows.size() + 4 * coverage.size());
  CHECK(lines[0] == "# Measurement snapshot of chapter 10's report, tiny setting");
  CHECK(lines[1].starts_with("# machine: " + run.report.machine.cpu_model));
  CHECK(lines[2] ==
        "# compiler: " + run.report.machine.compiler + " (" + run.report.machine.build_type + ")");
  CHECK(lines[3] == "# commit: 0123abc");
  CHECK(lines[4] == "# date: 2026-01-02");
  CHECK(lines[5] == "# peers: pixman 1.2");
  CHECK(lines[6] == "# note: shared");
  CHECK(lines[7] == "key,value");
  // The summaries come first, in the report's order, each led by its chapter.
  CHECK(lines[8] == summaries.front().algorithm + ".chapter," + summaries.front().chapter);
  CHECK(lines[8 + 8] == summaries[1].algorithm + ".chapter," + summaries[1].chapter);
  std::map<std::string, std::string> values;
  for (std::size_t i = 8; i < lines.size(); ++i) {
    const auto comma = lines[i].find(',');
    REQUIRE(comma != std::string::npos);
    const std::string key = lines[i].substr(0, comma);
    CHECK(key.find('/') == std::string::npos);  // a ratio marker splits its keys at '/'
    CHECK(values.emplace(key, lines[i].substr(comma + 1)).second);  // every key once
  }
  CHECK(values.at(summaries.front().algorithm + ".threaded") ==
        (summaries.front().threaded ? "1" : "0"));
  CHECK(values.at("area_cells.cost_vs_fastest") ==
        tri::format_number(coverage.front().cost_vs_fastest, 6));
  const tri::ch10::Measurement& row = run.report.rows.back();
  std::string grid = row.grid;
  std::replace(grid.begin(), grid.end(), '/', '_');
  CHECK(values.at(row.algorithm + "." + row.scene + "_" + grid + ".median_s") ==
        tri::format_number(row.timing.seconds.median, 6));
}

// The drawers of Blend2D's shapes (bl_bench's FillTriangle) in the tiny run, in its order: the
// aliased algorithms, the coverage algorithms, the peers, the anti-aliasing peers.
std::vector<std::string> shape_drawers() {
  std::vector<std::string> names = tiny_algorithms;
  for (const std::string& name : tiny_area_algorithms) names.push_back(name);
  for (const tri::ExternalPeer& peer : tiny_run().peers) names.emplace_back(peer.name);
  for (const tri::CoveragePeer& peer : tri::coverage_peers()) names.emplace_back(peer.name);
  return names;
}

TEST_CASE("Blend2D's shapes are drawn by every drawer at every size, the scenes its boxes",
          "[10_speed_vs_error][blend2d]") {
  const auto& rows = tiny_run().shapes;
  const auto names = shape_drawers();
  REQUIRE(rows.size() == names.size() * tri::ch10::blend2d_box_sides.size());
  for (std::size_t s = 0; s < tri::ch10::blend2d_box_sides.size(); ++s) {
    const int side = tri::ch10::blend2d_box_sides[s];
    const tri::SuiteScene scene = tri::ch10::blend2d_shape_scene(side, 4);
    CHECK(scene.recipe.kind == tri::SceneRecipe::Kind::in_boxes);
    CHECK(scene.recipe.box_side == side);
    CHECK(scene.recipe.width == 512);
    CHECK(scene.recipe.height == 600);
    for (std::size_t d = 0; d < names.size(); ++d) {
      const tri::ch10::ShapeRate& row = rows[s * names.size() + d];
      INFO(row.drawer << " at " << side);
      CHECK(row.drawer == names[d]);
      CHECK(row.box_side == side);
      CHECK(row.triangles == 4u);
      CHECK(row.timing.samples == 1);
      // bl_bench's rate: render calls (triangles) per millisecond of the median frame.
      CHECK(row.calls_per_ms() == 4 / (row.timing.seconds.median * 1000));
      CHECK(row.calls_per_ms() > 0);
    }
  }
  CHECK(lines_of(tiny_run().shapes_progress.str()).size() == rows.size());
}

TEST_CASE("The shapes' JSON file has bl_bench's layout: one positive rate per size per drawer",
          "[10_speed_vs_error][blend2d]") {
  const Json json = JsonParser(tiny_run().files.blend2d_shapes_json).document();
  CHECK(json.at("screen").at("width").number == 512);
  CHECK(json.at("screen").at("height").number == 600);
  CHECK(json.at("cpu").at("brand").text == tiny_run().report.machine.cpu_model);
  CHECK(json.at("cpu").at("instructionSet").text == tri::ch10::host_instruction_set());
  CHECK(json.at("options").at("quantity").number == 4);
  const auto& sizes = json.at("options").at("sizes").items;
  REQUIRE(sizes.size() == 6u);
  const char* expected_sizes[] = {"8x8", "16x16", "32x32", "64x64", "128x128", "256x256"};
  for (std::size_t i = 0; i < sizes.size(); ++i) CHECK(sizes[i].text == expected_sizes[i]);
  const auto names = shape_drawers();
  const auto& runs = json.at("runs").items;
  REQUIRE(runs.size() == names.size());
  for (std::size_t d = 0; d < runs.size(); ++d) {
    INFO(names[d]);
    CHECK(runs[d].at("name").text == names[d]);
    const auto& records = runs[d].at("records").items;
    REQUIRE(records.size() == 1u);
    CHECK(records[0].at("test").text == "FillTriangle");
    CHECK(records[0].at("style").text == "Solid");
    const auto& rates = records[0].at("rcpms").items;
    REQUIRE(rates.size() == 6u);
    for (std::size_t s = 0; s < rates.size(); ++s) {
      CHECK(rates[s].kind == Json::Kind::number);
      CHECK(rates[s].number > 0);
      // The row's rate as bl_bench rounds it: 4 decimals up to 0.1, then 3 significant digits
      // or more, so within half a unit of 0.0001 or 0.5% of the rate.
      const double rate = tiny_run().shapes[s * names.size() + d].calls_per_ms();
      CHECK(std::abs(rates[s].number - rate) <= std::max(0.00005, 0.005 * rate) * (1 + 1e-9));
    }
  }
  // An aliased algorithm replaces; chapter 09's area_cells adds its coverage.
  CHECK(runs[0].at("records").items[0].at("compOp").text == "SrcCopy");
  const auto area = std::find(names.begin(), names.end(), "area_cells") - names.begin();
  CHECK(runs[area].at("records").items[0].at("compOp").text == "Plus");
}

TEST_CASE("The Markdown has the shapes' section: a row per drawer, a column per size",
          "[10_speed_vs_error][blend2d]") {
  const std::string& md = tiny_run().files.markdown;
  REQUIRE_THAT(md, Catch::Contains("## Blend2D's benchmark shapes"));
  const std::string section = md.substr(md.find("## Blend2D's benchmark shapes"));
  CHECK_THAT(section, Catch::Contains("| drawer | chapter | writes | 8x8 | 16x16 | 32x32 | 64x64 | "
                                      "128x128 | 256x256 |"));
  CHECK_THAT(section, Catch::Contains(tri::ch10::host_instruction_set()));
  CHECK_THAT(section, Catch::Contains(tiny_run().report.machine.cpu_model));
  for (const std::string& name : shape_drawers()) {
    CHECK(occurrences(section, "| " + name + " |") == 1);
  }
  CHECK_THAT(section, Catch::Contains("| area_cells | 09_anti_aliasing | add |"));
  CHECK(occurrences(section, " | replace |") == tiny_algorithms.size());
  CHECK_THAT(section, Catch::Contains("not measured"));
  const auto csv = lines_of(tiny_run().files.blend2d_shapes_csv);
  REQUIRE(csv.size() == tiny_run().shapes.size() + 1);
  for (const std::string& line : csv) CHECK(occurrences(line, ",") == occurrences(csv[0], ","));
  CHECK(tri::ch10::blend2d_shapes_markdown({}, tiny_run().report.machine).empty());
}

TEST_CASE("The snapshot adds a rate per drawer and size of Blend2D's shapes, and the vectors",
          "[10_speed_vs_error][snapshot][blend2d]") {
  const TinyRun& run = tiny_run();
  const tri::ch10::SnapshotHeader header{"0123abc", "2026-01-02", "pixman 1.2", ""};
  const auto without = lines_of(tri::ch10::snapshot_text(run.report, run.coverage, header));
  const auto with =
      lines_of(tri::ch10::snapshot_text(run.report, run.coverage, header, run.shapes));
  REQUIRE(with.size() == without.size() + 1 + run.shapes.size());
  CHECK(std::equal(without.begin(), without.end(), with.begin()));
  CHECK(with[without.size()] == "blend2d_shapes.vectors," + tri::ch10::host_instruction_set());
  for (std::size_t i = 0; i < run.shapes.size(); ++i) {
    const tri::ch10::ShapeRate& r = run.shapes[i];
    CHECK(with[without.size() + 1 + i] == r.drawer + ".blend2d_" + std::to_string(r.box_side) +
                                              ".calls_per_ms," +
                                              tri::format_number(r.calls_per_ms(), 6));
  }
}
