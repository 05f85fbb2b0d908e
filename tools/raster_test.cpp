#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <random>
#include <regex>
#include <set>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include "chapters/01_lines/line_reference.hpp"
#include "chapters/09_anti_aliasing/area_oracle.hpp"
#include "chapters/09_anti_aliasing/coverage_canvas.hpp"
#include "chapters/09_anti_aliasing/sampling.hpp"
#include "common/scene.hpp"
#include "measure/area_error.hpp"
#include "measure/drawable.hpp"
#include "measure/registry.hpp"
#include "measure/render_scene.hpp"
#include "tests/support/in_process_run.hpp"
#include "tests/support/scratch_folder.hpp"
#include "tools/raster_app.hpp"

namespace fs = std::filesystem;

namespace {

// A fresh folder per test case (the scratch folder), with the writes and the count the tests use.
class TempFolder {
 public:
  fs::path write(const std::string& name, const std::string& text) const {
    tri::testing::write_text(folder_ / name, text);
    return folder_ / name;
  }
  fs::path operator/(const std::string& name) const { return folder_ / name; }
  std::size_t file_count() const { return tri::testing::names_in(folder_.path()).size(); }

 private:
  tri::testing::ScratchFolder folder_{"raster_test"};
};

using Run = tri::testing::InProcessRun;

Run raster(const std::vector<std::string>& args) {
  return tri::testing::run_in_process(
      "raster", args, [](int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
        return tri::run_raster(argc, argv, out, err);
      });
}

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The run failed with this exit status (1: an error, 2: a usage error) and said why.
void check_fails(const Run& run, int status, const std::string& message) {
  CHECK(run.status == status);
  CHECK(run.err.find(message) != std::string::npos);
}

// A usage error: raster run with these arguments exits with status 2 and says this.
struct Refusal {
  std::vector<std::string> args;
  std::string message;
};

// Each run is refused as it says, and the folder still holds only the scene written into it.
void check_refusals(const TempFolder& dir, std::initializer_list<Refusal> refusals) {
  for (const Refusal& refusal : refusals) {
    INFO(refusal.message);
    check_fails(raster(refusal.args), 2, refusal.message);
  }
  CHECK(dir.file_count() == 1);
}

// What --bench prints: the preparation line, then the speed line of this many triangles and frames.
std::regex bench_lines(int triangles, int frames) {
  return std::regex(
      "preparation_seconds=[0-9.e+-]+\n"
      "triangles=" +
      std::to_string(triangles) + " frames=" + std::to_string(frames) +
      " seconds=[0-9.e+-]+ min_seconds=[0-9.e+-]+ max_seconds=[0-9.e+-]+ "
      "tris_per_s=[0-9.e+-]+ mpix_per_s=[0-9.e+-]+\n");
}

bool is_one_line(const std::string& text) {
  return !text.empty() && text.back() == '\n' && text.find('\n') == text.size() - 1;
}

// The largest difference between a 16-bit coverage PGM (rows top first, after a header of
// header_size bytes) and truth_16(x, y), the expected value of pixel (x, y) with y up.
template <typename Truth>
int worst_coverage_error(const std::string& pgm, std::size_t header_size, int width, int height,
                         Truth truth_16) {
  int worst = 0;
  for (int row = 0; row < height; ++row) {
    for (int x = 0; x < width; ++x) {
      const std::size_t k = header_size + 2 * static_cast<std::size_t>(row * width + x);
      const int value =
          (static_cast<unsigned char>(pgm[k]) << 8) | static_cast<unsigned char>(pgm[k + 1]);
      worst = std::max(worst, std::abs(value - truth_16(x, height - 1 - row)));
    }
  }
  return worst;
}

}  // namespace

TEST_CASE("raster --help describes every form of the command", "[raster]") {
  const Run run = raster({"--help"});
  CHECK(run.status == 0);
  CHECK(run.err.empty());
  for (const char* text : {"--list", "--algo NAME", "--scene FILE", "--out FILE.png",
                           "--counts FILE.pgm", "--bench N"}) {
    CHECK(run.out.find(text) != std::string::npos);
  }
}

// The names --help gives after "index8 and mask1 are drawn by ", split at ", " and " and ".
std::vector<std::string> help_narrow_writers(std::span<const tri::Drawable> drawables) {
  const char* argv[] = {"raster", "--help"};
  std::ostringstream out, err;
  REQUIRE(tri::run_raster(drawables, 2, argv, out, err) == 0);
  const std::string help = out.str();
  const std::string before = "index8 and mask1 are drawn by ";
  const std::size_t start = help.find(before);
  REQUIRE(start != std::string::npos);
  const std::size_t from = start + before.size();
  const std::size_t end = help.find(" and expanded for the PNG", from);
  REQUIRE(end != std::string::npos);
  std::string list = std::regex_replace(help.substr(from, end - from), std::regex(" and "), ", ");
  std::vector<std::string> names;
  std::istringstream parts(list);
  for (std::string name; std::getline(parts, name, ',');) {
    names.push_back(name.substr(name.find_first_not_of(' ')));
  }
  return names;
}

// The drawables that declare both narrow formats, by name.
std::vector<std::string> declared_narrow_writers(std::span<const tri::Drawable> drawables) {
  std::vector<std::string> names;
  for (const tri::Drawable* d : tri::drawables_writing(drawables, tri::Output::index8)) {
    if (d->writes(tri::Output::mask1)) names.emplace_back(d->name);
  }
  return names;
}

TEST_CASE("raster --help names exactly the drawables that declare the narrow formats", "[raster]") {
  std::vector<tri::Drawable> drawables = tri::registered_drawables();
  const std::vector<std::string> declared = declared_narrow_writers(drawables);
  REQUIRE_FALSE(declared.empty());
  CHECK(help_narrow_writers(drawables) == declared);
  // Declaring the formats on one more drawable changes the help: the names come from descriptors.
  const auto colour_only = std::find_if(drawables.begin(), drawables.end(), [](const auto& d) {
    return d.colours != nullptr && !d.writes(tri::Output::index8);
  });
  REQUIRE(colour_only != drawables.end());
  colour_only->outputs = tri::narrow_outputs;
  const std::vector<std::string> widened = declared_narrow_writers(drawables);
  CHECK(widened.size() == declared.size() + 1);
  CHECK(help_narrow_writers(drawables) == widened);
}

TEST_CASE("raster --list prints one tab-separated line per registered algorithm", "[raster]") {
  const Run run = raster({"--list"});
  REQUIRE(run.status == 0);
  std::vector<std::string> names;
  for (const auto& a : tri::registered_algorithms()) names.emplace_back(a.name);
  const std::size_t triangle_algorithms = names.size();
  for (const auto& a : tri::registered_area_algorithms()) names.emplace_back(a.name);
  std::istringstream lines(run.out);
  std::string line;
  std::size_t count = 0;
  const std::regex format(
      "[a-z0-9_]+\t[0-9]{2}_[a-z_]+\t(top-left|inclusive|approximate|area)\t.+");
  while (std::getline(lines, line)) {
    CHECK(std::regex_match(line, format));
    REQUIRE(count < names.size());
    CHECK(line.starts_with(names[count] + "\t"));
    // The coverage algorithms come last, each with rule area.
    CHECK((line.find("\tarea\t") != std::string::npos) == (count >= triangle_algorithms));
    ++count;
  }
  CHECK(count == names.size());
}

TEST_CASE("The registry lists the algorithms of every chapter that fills triangles", "[raster]") {
  std::set<std::string> chapters;
  for (const auto& a : tri::registered_algorithms()) chapters.emplace(a.chapter);
  CHECK(chapters == std::set<std::string>{"03_interpolate_fill", "04_scanline", "05_edge_function",
                                          "06_barycentric", "07_exact_coverage", "08_fast_exact"});
}

TEST_CASE("raster draws a scene's lines with chapter 01's Bresenham and writes PNG and counts",
          "[raster]") {
  TempFolder dir;
  const auto scene = dir.write("lines.scene",
                               "# two lines\ncanvas 16 8 0 0 64\n"
                               "line 0 0 15 7 255 0 0\n"
                               "line 2.4 6.6 9.4 1 0 255 0  # rounds to (2,7)-(9,1)\n");
  const Run run = raster({"--scene", scene.string(), "--out", (dir / "a.png").string(), "--counts",
                          (dir / "a.pgm").string()});
  REQUIRE(run.status == 0);
  CHECK(run.out == "drew 0 triangle(s) and 2 line(s) on 16x8\n");
  const std::string png = read_file(dir / "a.png");
  REQUIRE(png.size() > 8);
  CHECK(png.substr(1, 3) == "PNG");

  // Expected counts: the exact nearest pixels (neither line has a tie), top row first.
  std::vector<int> counts(16 * 8, 0);
  for (const auto& [a, b] : {std::pair{glm::ivec2(0, 0), glm::ivec2(15, 7)},
                             std::pair{glm::ivec2(2, 7), glm::ivec2(9, 1)}}) {
    for (const auto& p : tri::ch01::exact_line_pixels(a, b)) {
      REQUIRE_FALSE(p.tie);
      ++counts[static_cast<std::size_t>((7 - p.pixel.y) * 16 + p.pixel.x)];
    }
  }
  const std::string pgm = read_file(dir / "a.pgm");
  const std::string header = "P5\n16 8\n255\n";
  REQUIRE(pgm.size() == header.size() + counts.size());
  CHECK(pgm.substr(0, header.size()) == header);
  for (std::size_t i = 0; i < counts.size(); ++i) {
    CHECK(static_cast<int>(static_cast<unsigned char>(pgm[header.size() + i])) == counts[i]);
  }
}

TEST_CASE("raster rejects an unknown algorithm in one line and writes nothing", "[raster]") {
  TempFolder dir;
  const auto scene = dir.write("s.scene", "canvas 8 8\ntri 0 0 7 0 0 7\n");
  const Run run = raster({"--algo", "no_such_algorithm", "--scene", scene.string(), "--out",
                          (dir / "x.png").string()});
  CHECK(run.status != 0);
  CHECK(is_one_line(run.err));
  CHECK(run.err.find("unknown algorithm 'no_such_algorithm'") != std::string::npos);
  CHECK_FALSE(fs::exists(dir / "x.png"));
  CHECK(dir.file_count() == 1);
}

TEST_CASE("raster rejects a malformed scene with file and line and writes nothing", "[raster]") {
  TempFolder dir;
  const auto scene = dir.write("bad.scene", "canvas 8 8\nline 0 0 7 7\nline 0 zero 3 3\n");
  const Run run = raster({"--scene", scene.string(), "--out", (dir / "x.png").string(), "--counts",
                          (dir / "x.pgm").string()});
  CHECK(run.status == 1);
  CHECK(is_one_line(run.err));
  CHECK(run.err.find(scene.string() + ":3: expected a decimal number for y0, got 'zero'") !=
        std::string::npos);
  CHECK(dir.file_count() == 1);
}

TEST_CASE("raster rejects NaN and infinite coordinates and writes nothing", "[raster]") {
  TempFolder dir;
  const auto word = GENERATE(as<std::string>{}, "nan", "NaN", "inf", "-inf", "infinity");
  const auto scene = dir.write("nan.scene", "canvas 8 8\nline 0 0 " + word + " 7\n");
  const Run run = raster({"--scene", scene.string(), "--out", (dir / "x.png").string()});
  CHECK(run.status == 1);
  CHECK(is_one_line(run.err));
  CHECK(run.err.find(scene.string() + ":2: x1 is") != std::string::npos);
  CHECK(dir.file_count() == 1);
}

TEST_CASE("raster asks for an algorithm when the scene has triangles", "[raster]") {
  TempFolder dir;
  const auto scene = dir.write("t.scene", "canvas 8 8\ntri 0 0 7 0 0 7\n");
  check_refusals(dir, {{{"--scene", scene.string(), "--out", (dir / "x.png").string()},
                        "choose an algorithm with --algo"}});
}

TEST_CASE("raster reports a missing scene file, a missing --scene and bad option mixes",
          "[raster]") {
  TempFolder dir;
  Run run = raster({"--scene", (dir / "none.scene").string()});
  check_fails(run, 1, "none.scene: cannot open the scene file");
  run = raster({"--out", (dir / "x.png").string()});
  check_fails(run, 2, "--scene FILE is required");
  run = raster({"--list", "--algo", "x"});
  CHECK(run.status == 2);
  const auto scene = dir.write("l.scene", "canvas 8 8\nline 0 0 7 7\n");
  run = raster({"--scene", scene.string(), "--bench", "3", "--out", (dir / "x.png").string()});
  CHECK(run.status == 2);
  run = raster({"--scene", scene.string(), "--bench", "0"});
  CHECK(run.status == 2);
  CHECK(dir.file_count() == 1);
}

TEST_CASE("raster --bench prints the preparation line and the speed line", "[raster][bench]") {
  TempFolder dir;
  const auto scene = dir.write("l.scene", "canvas 8 8\nline 0 0 7 7\nline 0 7 7 0\n");
  const Run run = raster({"--scene", scene.string(), "--bench", "5"});
  REQUIRE(run.status == 0);
  CHECK(std::regex_match(run.out, bench_lines(0, 5)));
  CHECK(dir.file_count() == 1);
}

TEST_CASE("raster keeps the earlier picture when a later output fails", "[raster]") {
  TempFolder dir;
  const auto scene = dir.write("l.scene", "canvas 8 8\nline 0 0 7 7\n");
  const auto previous = dir.write("prev.png", "the earlier picture");
  fs::create_directory(dir / "somedir");
  const Run run = raster({"--scene", scene.string(), "--out", previous.string(), "--counts",
                          (dir / "somedir").string()});
  CHECK(run.status == 1);
  CHECK(is_one_line(run.err));
  CHECK(run.err.find((dir / "somedir").string() + ": Is a directory") != std::string::npos);
  CHECK(read_file(previous) == "the earlier picture");
  CHECK(dir.file_count() == 3);  // the scene, prev.png, somedir: no temporary left
}

TEST_CASE("raster refuses its scene as an output before drawing, and the scene survives",
          "[raster]") {
  TempFolder dir;
  const std::string text = "canvas 8 8\nline 0 0 7 7\n";
  const auto scene = dir.write("s.scene", text);
  for (const char* option : {"--out", "--counts"}) {
    const Run run = raster({"--scene", scene.string(), option, scene.string()});
    check_fails(run, 2, "is the input");
    CHECK(read_file(scene) == text);
  }
  fs::create_hard_link(scene, dir / "alias.png");
  const Run run = raster({"--scene", scene.string(), "--out", (dir / "alias.png").string()});
  CHECK(run.status == 2);
  CHECK(read_file(scene) == text);
}

TEST_CASE("raster refuses two outputs naming one file and empty output paths", "[raster]") {
  TempFolder dir;
  const auto scene = dir.write("s.scene", "canvas 8 8\n");
  const auto same = (dir / "x").string();
  check_refusals(dir, {{{"--scene", scene.string(), "--out", same, "--counts", same},
                        "two outputs name one file"},
                       {{"--scene", scene.string(), "--out", ""}, "needs a non-empty value"}});
}

TEST_CASE("raster refuses an output ending in a slash before reading the scene and makes nothing",
          "[raster]") {
  TempFolder dir;
  // A malformed scene: the refusal comes first, so no work was done before it.
  const auto scene = dir.write("s.scene", "canvas 8 8\nbogus\n");
  const std::string folder_like = (dir / "x.png").string() + "/";
  for (const std::vector<std::string>& options :
       {std::vector<std::string>{"--out", folder_like},
        std::vector<std::string>{"--counts", folder_like},
        std::vector<std::string>{"--algo", "area_cells", "--coverage", folder_like}}) {
    std::vector<std::string> args{"--scene", scene.string()};
    args.insert(args.end(), options.begin(), options.end());
    const Run run = raster(args);
    check_fails(run, 2, "drop the trailing slash");
    CHECK(is_one_line(run.err));
  }
  CHECK(dir.file_count() == 1);
}

TEST_CASE("raster refuses to replace a device and leaves it a device", "[raster]") {
  TempFolder dir;
  const auto scene = dir.write("s.scene", "canvas 8 8\n");
  const Run run = raster({"--scene", scene.string(), "--out", "/dev/null"});
  check_fails(run, 1, "/dev/null: it is a character device");
  CHECK(fs::is_character_file("/dev/null"));
}

TEST_CASE("raster --out - writes the PNG to standard output and the summary to errors",
          "[raster]") {
  TempFolder dir;
  const auto scene = dir.write("s.scene", "canvas 8 8\nline 0 0 7 7\n");
  const Run run = raster({"--scene", scene.string(), "--out", "-"});
  REQUIRE(run.status == 0);
  CHECK(run.out.substr(1, 3) == "PNG");
  CHECK(run.err == "drew 0 triangle(s) and 1 line(s) on 8x8\n");
  CHECK_FALSE(fs::exists("-"));
}

TEST_CASE("raster --list into a full standard output fails with the system's reason", "[raster]") {
  std::ofstream full("/dev/full");
  const char* argv[] = {"raster", "--list"};
  std::ostringstream err;
  CHECK(tri::run_raster(2, argv, full, err) == 1);
  CHECK(err.str().find("No space left on device") != std::string::npos);
}

TEST_CASE("raster names the system's reason for a scene it cannot open", "[raster]") {
  TempFolder dir;
  const Run missing = raster({"--scene", (dir / "none.scene").string()});
  CHECK(missing.status == 1);
  CHECK(missing.err.find("No such file or directory") != std::string::npos);
  const Run folder = raster({"--scene", (dir / ".").string()});
  CHECK(folder.status == 1);
  CHECK(folder.err.find("Is a directory") != std::string::npos);
}

TEST_CASE("raster --bench refuses a count estimated beyond ten minutes unless forced",
          "[raster][bench]") {
  TempFolder dir;
  const auto scene = dir.write("big.scene", "canvas 2048 2048\ntri -10 -10 5000 -10 -10 5000\n");
  Run run = raster({"--algo", "edge_function", "--scene", scene.string(), "--bench", "1000000"});
  check_fails(run, 2, "add --force to run it anyway");
  CHECK(run.out.empty());
  run = raster({"--algo", "edge_function", "--scene", scene.string(), "--force"});
  check_fails(run, 2, "--force goes with --bench");
}

TEST_CASE("raster draws the same picture with progress pieces as in one batch", "[raster]") {
  std::string text = "canvas 64 48\n";
  for (int i = 0; i < 300; ++i) {
    text += "tri " + std::to_string(i % 50) + " 0 63 " + std::to_string(i % 40) + " 5 47 " +
            std::to_string(i % 256) + " 7 9\n";
    if (i % 17 == 0) text += "line 0 0 63 " + std::to_string(i % 48) + "\n";
  }
  std::istringstream in(text);
  const tri::Scene scene = tri::parse_scene(in, "pieces");
  for (const auto& algorithm : tri::registered_algorithms()) {
    INFO(algorithm.name);
    tri::Canvas whole = tri::make_canvas(scene), pieces = tri::make_canvas(scene);
    tri::render_scene(scene, &algorithm, whole);
    std::size_t reports = 0;
    tri::render_scene(scene, &algorithm, pieces, [&](std::size_t) { ++reports; });
    CHECK(reports > 0);
    CHECK(std::equal(whole.pixels().begin(), whole.pixels().end(), pieces.pixels().begin(),
                     [](tri::Color a, tri::Color b) {
                       return a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a;
                     }));
  }
}

TEST_CASE(
    "raster --coverage writes the 16-bit PGM of the contract, within a unit of the exact area",
    "[raster][coverage]") {
  TempFolder dir;
  const auto scene = dir.write("c.scene",
                               "canvas 12 9\n"
                               "tri 0.5 0.25 10.75 2.5 3.125 8.5\n"
                               "tri 10.75 2.5 11.5 8.75 3.125 8.5\n"
                               "line 0 0 11 8\n");
  const Run run = raster(
      {"--algo", "area_cells", "--scene", scene.string(), "--coverage", (dir / "c.pgm").string()});
  REQUIRE(run.status == 0);
  CHECK(run.out ==
        "drew the coverage of 2 triangle(s) on 12x9 with area_cells (1 line(s) left out: a line "
        "has no area)\n");
  const std::string pgm = read_file(dir / "c.pgm");
  const std::string header = "P5\n12 9\n65535\n";
  REQUIRE(pgm.size() == header.size() + 12 * 9 * 2);
  CHECK(pgm.substr(0, header.size()) == header);
  // The two triangles share an edge, so the exact coverages add up: the truth, top row first.
  const tri::Triangle a = {{{0.5, 0.25}, {10.75, 2.5}, {3.125, 8.5}}};
  const tri::Triangle b = {{{10.75, 2.5}, {11.5, 8.75}, {3.125, 8.5}}};
  CHECK(worst_coverage_error(pgm, header.size(), 12, 9, [&](int x, int y) {
          return tri::ch09::coverage_16(tri::ch09::exact_coverage(a, {x, y}) +
                                        tri::ch09::exact_coverage(b, {x, y}));
        }) <= 1);
}

TEST_CASE("raster --coverage draws vertices a subnormal distance apart as their grid triangles",
          "[raster][coverage]") {
  TempFolder dir;
  const auto scene = dir.write("s.scene",
                               "canvas 16 16\n"
                               "tri 15 0 1e-310 1e-310 0 15\n"
                               "tri 15 0 0 0 1e-310 15\n"
                               "tri 0 0 10 5 5e-324 10\n");
  const std::vector<tri::Triangle> grid = {
      {{{15, 0}, {0, 0}, {0, 15}}}, {{{15, 0}, {0, 0}, {0, 15}}}, {{{0, 0}, {10, 5}, {0, 10}}}};
  for (const std::string algorithm : {"area_cells", "area_cells_over"}) {
    const std::string pgm_path = (dir / (algorithm + ".pgm")).string();
    const Run run =
        raster({"--algo", algorithm, "--scene", scene.string(), "--coverage", pgm_path});
    INFO(algorithm << ": " << run.err);
    REQUIRE(run.status == 0);
    const std::string pgm = read_file(pgm_path);
    const std::string header = "P5\n16 16\n65535\n";
    REQUIRE(pgm.size() == header.size() + 16 * 16 * 2);
    CHECK(worst_coverage_error(pgm, header.size(), 16, 16, [&](int x, int y) {
            // Composited over, each triangle's exact coverage e joins the pixel as v + e (1 - v).
            double truth = 0;
            for (const tri::Triangle& t : grid) {
              const double e = tri::ch09::exact_coverage(t, {x, y}).to_double();
              truth = algorithm == "area_cells" ? truth + e : truth + e * (1 - truth);
            }
            return tri::ch09::coverage_16(truth);
          }) <= 1);
  }
}

TEST_CASE("raster refuses --coverage without a rule-area algorithm and colours with one",
          "[raster][coverage]") {
  TempFolder dir;
  const auto scene = dir.write("t.scene", "canvas 8 8\ntri 0 0 7 0 0 7\n");
  const std::vector<std::string> aliased_coverage{
      "--algo", "fast_hybrid", "--scene", scene.string(), "--coverage", (dir / "x.pgm").string()};
  check_refusals(
      dir, {{aliased_coverage, "--coverage needs an algorithm of rule area"},
            {aliased_coverage, "fast_hybrid has rule top-left"},
            {{"--algo", "area_cells", "--scene", scene.string(), "--out", (dir / "x.png").string()},
             "area_cells has rule area"},
            {{"--algo", "samples_grid_4x4", "--scene", scene.string()},
             "choose --coverage FILE.pgm or --bench N"}});
}

TEST_CASE("raster --coverage refuses an out-of-range scene and keeps the earlier file",
          "[raster][coverage]") {
  TempFolder dir;
  const auto scene = dir.write("far.scene", "canvas 8 8\ntri 0 0 7 0 0 7\ntri 0 0 1e12 0 0 7\n");
  const auto earlier = dir.write("c.pgm", "earlier");
  const Run run =
      raster({"--algo", "area_cells", "--scene", scene.string(), "--coverage", earlier.string()});
  CHECK(run.status == 1);
  CHECK(is_one_line(run.err));
  CHECK(run.err.find(scene.string() + ":3: x1 1e12 is outside ±2^30") != std::string::npos);
  CHECK(read_file(earlier) == "earlier");
  CHECK(dir.file_count() == 2);
}

TEST_CASE("raster --bench times a rule-area algorithm with the preparation and speed lines",
          "[raster][coverage]") {
  TempFolder dir;
  const auto scene = dir.write("t.scene", "canvas 8 8\ntri 0 0 7 0 0 7\n");
  const Run run =
      raster({"--algo", "samples_standard_4", "--scene", scene.string(), "--bench", "3"});
  REQUIRE(run.status == 0);
  CHECK(std::regex_match(run.out, bench_lines(1, 3)));
}

TEST_CASE("The rate of a rule-area algorithm counts the pixels each triangle touches",
          "[raster][coverage]") {
  const tri::Triangle t = {{{0, 0}, {7, 0}, {0, 7}}};
  const auto pattern = tri::ch09::standard_pattern(4);
  std::uint64_t sampled = 0;
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 8; ++x) sampled += tri::ch09::sampled_coverage(t, {x, y}, pattern) > 0;
  }
  const auto algorithms = tri::registered_area_algorithms();
  const auto* standard_4 = tri::find_named(algorithms, "samples_standard_4");
  REQUIRE(standard_4 != nullptr);
  const std::vector<tri::SceneTriangle> twice = {{t}, {t}};
  CHECK(sampled > 28);
  CHECK(tri::touched_pixels(*standard_4, 8, 8, twice) == 2 * sampled);
}

namespace {

// A scene of `count` overlapping triangles on the 1/256 grid, partly off the 97x61 canvas, in
// `colors` colours taken in turn.
std::string random_scene(int count, int colors, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_int_distribution<int> x(-10 * 256, 107 * 256), y(-10 * 256, 71 * 256);
  std::ostringstream scene;
  scene << "canvas 97 61 10 20 30\n";
  for (int i = 0; i < count; ++i) {
    scene << "tri";
    for (int v = 0; v < 3; ++v) scene << ' ' << x(random) / 256.0 << ' ' << y(random) / 256.0;
    scene << ' ' << 40 * (i % colors) << " 100 " << 250 - 50 * (i % colors) << '\n';
  }
  return scene.str();
}

}  // namespace

TEST_CASE("raster --format index8 and mask1 give the RGBA8 picture, byte for byte",
          "[raster][format]") {
  TempFolder dir;
  for (const auto& [colors, format] :
       std::vector<std::pair<int, std::string>>{{1, "mask1"}, {1, "index8"}, {3, "index8"}}) {
    CAPTURE(colors, format);
    const auto scene = dir.write("s.scene", random_scene(60, colors, 5 + colors));
    const Run rgba = raster(
        {"--algo", "fast_spans", "--scene", scene.string(), "--out", (dir / "rgba8.png").string()});
    const Run narrow = raster({"--algo", "fast_spans", "--scene", scene.string(), "--format",
                               format, "--out", (dir / "narrow.png").string()});
    REQUIRE(rgba.status == 0);
    REQUIRE(narrow.status == 0);
    CHECK(narrow.out ==
          "drew 60 triangle(s) and 0 line(s) on 97x61 with fast_spans as " + format + "\n");
    CHECK(read_file(dir / "narrow.png") == read_file(dir / "rgba8.png"));
  }
}

TEST_CASE("raster --format auto picks the narrowest format the scene and the algorithm allow",
          "[raster][format]") {
  TempFolder dir;
  const auto one = dir.write("one.scene", random_scene(10, 1, 1));
  const auto three = dir.write("three.scene", random_scene(10, 3, 2));
  const auto lines = dir.write("lines.scene", random_scene(10, 1, 3) + "line 0 0 20 20\n");
  const auto summary_ends = [&](const std::string& algo, const fs::path& scene,
                                const std::string& format) {
    const Run run = raster({"--algo", algo, "--scene", scene.string(), "--format", "auto"});
    CHECK(run.status == 0);
    CHECK(run.out.ends_with(" as " + format + "\n"));
  };
  summary_ends("fast_spans", one, "mask1");
  summary_ends("fast_spans", three, "index8");
  summary_ends("fast_spans", lines, "rgba8");  // a narrow format draws no lines
  summary_ends("fast_hybrid", one, "rgba8");   // it draws RGBA8 only
}

TEST_CASE(
    "raster refuses a format the algorithm or the scene cannot have, and keeps the earlier "
    "picture",
    "[raster][format]") {
  TempFolder dir;
  const auto three = dir.write("three.scene", random_scene(10, 3, 4));
  const auto previous = dir.write("prev.png", "the earlier picture");
  const auto refused = [&](std::vector<std::string> args, int status, const std::string& reason) {
    const Run run = raster(std::move(args));
    CHECK(run.status == status);
    CHECK(is_one_line(run.err));
    CHECK(run.err.find(reason) != std::string::npos);
    CHECK(read_file(previous) == "the earlier picture");
  };
  const std::string scene = three.string(), out = previous.string();
  refused(
      {"--algo", "fast_hybrid", "--scene", scene, "--format", "mask1", "--out", out}, 2,
      "fast_hybrid draws RGBA8 only; index8 and mask1 are drawn by fast_spans and fast_batched");
  refused({"--algo", "fast_spans", "--scene", scene, "--format", "mask1", "--out", out}, 1,
          "mask1 holds 1 colour besides the background, and the scene's triangles have 3");
  refused({"--algo", "fast_spans", "--scene", scene, "--format", "index8", "--counts", out}, 2,
          "--counts counts the writes of the RGBA8 canvas");
  refused({"--algo", "fast_spans", "--scene", scene, "--format", "bgr", "--out", out}, 2,
          "--format must be rgba8, index8, mask1 or auto, not 'bgr'");
  refused({"--algo", "area_cells", "--scene", scene, "--format", "index8", "--coverage", out}, 2,
          "area_cells has rule area: --format is for colour pictures");
}

TEST_CASE("raster --bench times a narrow format with the preparation and speed lines",
          "[raster][format][bench]") {
  TempFolder dir;
  const auto scene = dir.write("one.scene", random_scene(20, 1, 6));
  const Run run = raster(
      {"--algo", "fast_spans", "--scene", scene.string(), "--format", "mask1", "--bench", "3"});
  REQUIRE(run.status == 0);
  CHECK(std::regex_match(run.out, bench_lines(20, 3)));
}
