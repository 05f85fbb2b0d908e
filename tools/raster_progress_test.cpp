// raster's progress on every long path, its messages as one line of printable text, and what it
// says and needs when memory is short (docs/DESIGN.md section 9). Progress is scaled down with
// --progress-after 0, never by timing.
#include <catch2/catch.hpp>

#include <malloc.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <regex>
#include <sstream>
#include <streambuf>
#include <string>
#include <vector>

#include "chapters/09_anti_aliasing/coverage_canvas.hpp"
#include "common/scene.hpp"
#include "measure/registry.hpp"
#include "measure/render_scene.hpp"
#include "tests/support/in_process_run.hpp"
#include "tools/raster_app.hpp"

namespace fs = std::filesystem;

namespace {

// A folder of its own under the system's temporary folder, removed with everything in it.
class ScratchFolder {
 public:
  ScratchFolder() {
    std::string pattern = (fs::temp_directory_path() / "raster_progress_XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
    path_ = pattern;
  }
  ~ScratchFolder() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;

  fs::path file(const std::string& name, const std::string& text) const {
    std::ofstream(path_ / name, std::ios::binary) << text;
    return path_ / name;
  }
  fs::path operator/(const std::string& name) const { return path_ / name; }

 private:
  fs::path path_;
};

using Outcome = tri::testing::InProcessRun;

Outcome raster(const std::vector<std::string>& words) {
  return tri::testing::run_in_process(
      "raster", words, [](int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
        return tri::run_raster(argc, argv, out, err);
      });
}

// How many lines of err match the pattern.
std::size_t lines_matching(const std::string& err, const std::string& pattern) {
  const std::regex line(pattern);
  std::istringstream lines(err);
  std::size_t count = 0;
  for (std::string text; std::getline(lines, text);) count += std::regex_match(text, line);
  return count;
}

const std::string percent_left = ": [0-9]+% done, about [0-9]+ (s|min) left";

}  // namespace

TEST_CASE("raster --coverage reports its progress", "[raster][progress]") {
  ScratchFolder dir;
  std::string text = "canvas 64 64\n";
  for (int i = 0; i < 500; ++i) text += "tri 0 0 63 " + std::to_string(i % 64) + " 5 63\n";
  const auto scene = dir.file("many.scene", text);
  const Outcome quiet =
      raster({"--algo", "samples_grid_4x4", "--scene", scene.string(), "--coverage",
              (dir / "c.pgm").string(), "--progress-after", "3600"});
  REQUIRE(quiet.status == 0);
  CHECK(quiet.err.empty());
  const Outcome told = raster({"--algo", "samples_grid_4x4", "--scene", scene.string(),
                               "--coverage", (dir / "c.pgm").string(), "--progress-after", "0"});
  REQUIRE(told.status == 0);
  CHECK(lines_matching(told.err, "raster: coverage" + percent_left) > 0);
}

TEST_CASE("raster --format mask1 and index8 report progress and the PNG estimate",
          "[raster][progress][format]") {
  ScratchFolder dir;
  std::string text = "canvas 64 64\n";
  for (int i = 0; i < 3 * 4096; ++i) text += "tri 0 0 9 " + std::to_string(i % 9) + " 2 9\n";
  const auto scene = dir.file("many.scene", text);
  for (const char* format : {"mask1", "index8", "auto"}) {
    CAPTURE(format);
    const Outcome told =
        raster({"--algo", "fast_spans", "--scene", scene.string(), "--format", format, "--out",
                (dir / "x.png").string(), "--progress-after", "0"});
    REQUIRE(told.status == 0);
    CHECK(lines_matching(told.err, "raster: drawing" + percent_left) == 2);  // at 4096 and 8192
    CHECK(lines_matching(told.err, "raster: encoding a 64x64 PNG, about 0 s") == 1);
  }
}

TEST_CASE("raster splits a huge triangle into bands of rows and reports each",
          "[raster][progress]") {
  ScratchFolder dir;
  // 2048 x 2048 pixels under the triangle's box: four bands of band_pixels.
  const auto scene = dir.file("one.scene", "canvas 2048 2048\ntri -1 -1 4100 -1 -1 4100\n");
  const std::vector<std::vector<std::string>> forms = {
      {"--algo", "fast_spans"},
      {"--algo", "fast_hybrid", "--counts", (dir / "c.pgm").string()},
      {"--algo", "fast_spans", "--format", "mask1"},
      {"--algo", "samples_standard_2", "--coverage", (dir / "c16.pgm").string()},
  };
  for (const auto& form : forms) {
    CAPTURE(form);
    std::vector<std::string> words = form;
    for (const char* w : {"--scene", "", "--progress-after", "0"}) words.emplace_back(w);
    words[words.size() - 3] = scene.string();
    const Outcome told = raster(words);
    REQUIRE(told.status == 0);
    CHECK(lines_matching(told.err,
                         "raster: (drawing|coverage): (25|50|75)% done, about [0-9]+ s "
                         "left") == 3);
  }
}

TEST_CASE("raster reports the progress of reading a scene by bytes read", "[raster][progress]") {
  ScratchFolder dir;
  // Blank lines and comments: no primitive to count, only bytes.
  const std::string blank(3 * tri::scene_progress_bytes, '\n');
  const auto scene = dir.file("blank.scene", "canvas 4 4\n" + blank + "# end\n");
  const Outcome told = raster({"--scene", scene.string(), "--progress-after", "0"});
  REQUIRE(told.status == 0);
  CHECK(lines_matching(told.err, "raster: reading the scene" + percent_left) == 3);
  const Outcome quiet = raster({"--scene", scene.string()});
  CHECK(quiet.err.empty());
}

TEST_CASE("raster refuses a progress threshold that is not a whole number of seconds",
          "[raster][progress]") {
  const Outcome bad = raster({"--scene", "none.scene", "--progress-after", "-1"});
  CHECK(bad.status == 2);
  CHECK(bad.err.find("--progress-after expects a whole number from 0 to 86400") !=
        std::string::npos);
}

namespace {

// Triangles whose edges cross row boundaries on pixel centres (ties of the top-left rule),
// horizontal edges on centre rows, vertices on centres, and random ones on the 1/256 grid.
std::vector<tri::SceneTriangle> band_test_triangles() {
  std::vector<tri::SceneTriangle> triangles = {
      {{{{0, 0}, {30, 10}, {0, 20}}}, {200, 10, 10, 255}},             // edges through centres
      {{{{2, 3}, {25, 3}, {14, 17}}}, {10, 200, 10, 255}},             // horizontal bottom on a row
      {{{{2, 17}, {14, 3}, {25, 17}}}, {10, 10, 200, 255}},            // horizontal top on a row
      {{{{-5, 4.5}, {40, 4.5}, {17.5, 19.5}}}, {255, 255, 255, 255}},  // between rows
      {{{{3, 1}, {3, 18}, {28, 9.5}}}, {90, 90, 0, 255}},              // vertical edge on a column
      {{{{-100, -50}, {300, -50}, {-100, 400}}}, {1, 2, 3, 255}},      // covers the canvas
  };
  std::mt19937 random(7);
  std::uniform_int_distribution<int> x(-8 * 256, 40 * 256), y(-8 * 256, 28 * 256);
  for (int i = 0; i < 60; ++i) {
    tri::SceneTriangle t;
    for (auto& v : t.vertices) v = {x(random) / 256.0, y(random) / 256.0};
    t.color = {static_cast<std::uint8_t>(i * 4), 100, 50, 255};
    triangles.push_back(t);
  }
  return triangles;
}

}  // namespace

// Calls check(algorithm, rows) for every algorithm with a band-limited entry and a few band
// heights; returns how many algorithms have one.
template <class Algorithms, class Check>
std::size_t for_each_band_limited(const Algorithms& algorithms, Check check) {
  std::size_t checked = 0;
  for (const auto& algorithm : algorithms) {
    if (algorithm.draw_rows == nullptr) continue;
    ++checked;
    for (const int rows : {1, 2, 3, 7}) check(algorithm, rows);
  }
  return checked;
}

TEST_CASE(
    "Every band-limited entry draws, band by band, the pixels and write counts of the whole "
    "draw",
    "[raster][progress][bands]") {
  const auto triangles = band_test_triangles();
  const auto checked = for_each_band_limited(
      tri::registered_algorithms(), [&](const tri::TriangleAlgorithm& algorithm, int rows) {
        for (const tri::SceneTriangle& t : triangles) {
          CAPTURE(algorithm.name, rows, t.vertices[0].x, t.vertices[0].y);
          tri::Canvas whole(32, 21), banded(32, 21);
          whole.enable_write_counts();
          banded.enable_write_counts();
          algorithm.draw(whole, t.vertices, t.color);
          tri::for_each_band(t.vertices, 32, 21, rows, [&](int first, int last) {
            algorithm.draw_rows(banded, t.vertices, t.color, first, last);
          });
          CHECK(std::equal(whole.write_counts().begin(), whole.write_counts().end(),
                           banded.write_counts().begin(), banded.write_counts().end()));
          bool same = true;
          for (std::size_t i = 0; i < whole.pixels().size(); ++i) {
            const tri::Color a = whole.pixels()[i], b = banded.pixels()[i];
            same = same && a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a;
          }
          CHECK(same);
        }
      });
  CHECK(checked >= 6);  // chapter 08's one-thread variants
}

TEST_CASE("Every band-limited coverage entry adds, band by band, the values of the whole draw",
          "[raster][progress][bands][coverage]") {
  const auto triangles = band_test_triangles();
  const auto checked = for_each_band_limited(
      tri::registered_area_algorithms(), [&](const tri::ch09::AreaAlgorithm& algorithm, int rows) {
        CAPTURE(algorithm.name, rows);
        tri::ch09::CoverageCanvas whole(32, 21), banded(32, 21);
        for (const tri::SceneTriangle& t : triangles) {
          algorithm.draw(whole, std::span(&t, 1));
          tri::for_each_band(t.vertices, 32, 21, rows, [&](int first, int last) {
            algorithm.draw_rows(banded, t.vertices, first, last);
          });
        }
        bool same = true;
        for (int y = 0; y < 21; ++y) {
          for (int x = 0; x < 32; ++x) same = same && whole.at(x, y) == banded.at(x, y);
        }
        CHECK(same);
      });
  CHECK(checked == 9);  // the sampling algorithms
}

TEST_CASE(
    "render_scene with progress draws huge triangles in bands, with the same pixels and "
    "counts",
    "[raster][progress][bands]") {
  // Boxes of more than band_pixels pixels, so the progress path bands them.
  std::istringstream in(
      "canvas 2100 600\n"
      "tri -3 -2 2200 300.5 7 650 200 0 0\n"
      "line 0 0 2099 599\n"
      "tri 2101 -1 -1 299.5 2000 601 0 200 0\n"
      "tri 0 0 4 0 0 4 0 0 200\n");
  const tri::Scene scene = tri::parse_scene(in, "bands");
  for (const auto& algorithm : tri::registered_algorithms()) {
    if (algorithm.draw_rows == nullptr) continue;
    CAPTURE(algorithm.name);
    tri::Canvas whole = tri::make_canvas(scene), pieces = tri::make_canvas(scene);
    whole.enable_write_counts();
    pieces.enable_write_counts();
    tri::render_scene(scene, &algorithm, whole);
    std::vector<double> reports;
    tri::render_scene(scene, &algorithm, pieces, [&](double done) { reports.push_back(done); });
    // The first triangle's bands report fractions of it.
    CHECK(std::count_if(reports.begin(), reports.end(), [](double d) { return d > 0 && d < 1; }) >
          0);
    CHECK(std::equal(whole.write_counts().begin(), whole.write_counts().end(),
                     pieces.write_counts().begin(), pieces.write_counts().end()));
    CHECK(std::equal(whole.pixels().begin(), whole.pixels().end(), pieces.pixels().begin(),
                     [](tri::Color a, tri::Color b) {
                       return a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a;
                     }));
  }
}

TEST_CASE("raster escapes control, format and separator characters of paths and scene words",
          "[raster][messages]") {
  ScratchFolder dir;
  // A missing scene whose name holds ESC, BEL and a newline (it would set a terminal's title).
  const std::string sneaky = (dir / "a\x1b]0;owned\x07\nb.scene").string();
  Outcome o = raster({"--scene", sneaky});
  CHECK(o.status == 1);
  CHECK(o.err == "raster: error: " + (dir / "").string() +
                     "a\\x1B]0;owned\\x07\\x0Ab.scene: cannot open the scene file: No such file "
                     "or directory\n");
  // Bidirectional controls and the line separator in a path and in an option's value.
  const std::string reversed = (dir / "x\u202E\u2066gnp.\u2028scene").string();
  o = raster({"--scene", reversed});
  CHECK(o.status == 1);
  CHECK(o.err.find("x\\xE2\\x80\\xAE\\xE2\\x81\\xA6gnp.\\xE2\\x80\\xA8scene: cannot open") !=
        std::string::npos);
  CHECK(o.err.find('\n') == o.err.size() - 1);
  o = raster({"--list", "--format", "\u061Cx\u2060"});
  CHECK(o.status == 2);
  CHECK(o.err.find("--list takes no other option") != std::string::npos);
  o = raster({"--algo", "\u00ADno\u200Bsuch\x1b", "--scene", sneaky});
  CHECK(o.status == 2);
  CHECK(o.err.find("unknown algorithm '\\xC2\\xADno\\xE2\\x80\\x8Bsuch\\x1B'") !=
        std::string::npos);
  // An output under a plain file: the output code's message names the path, escaped.
  const auto plain = dir.file("plain", "");
  const auto lines = dir.file("l.scene", "canvas 4 4\nline 0 0 3 3\n");
  o = raster({"--scene", lines.string(), "--out", (plain / "p\x1b[2J\u2029.png").string()});
  CHECK(o.status != 0);
  CHECK(o.err.find("p\\x1B[2J\\xE2\\x80\\xA9.png") != std::string::npos);
  CHECK(o.err.find('\n') == o.err.size() - 1);
  // Words of a scene: a line separator and a tag character in a directive.
  const auto scene = dir.file("words.scene", "canvas 4 4\nli\u2028ne\U000E0041 0 0 1 1\n");
  o = raster({"--scene", scene.string()});
  CHECK(o.status == 1);
  CHECK(o.err.find(":2: unknown directive 'li\\xE2\\x80\\xA8ne\\xF3\\xA0\\x81\\x81'") !=
        std::string::npos);
}

namespace {

// Runs body in a child process and returns the text it returned there.
[[maybe_unused]] std::string in_child(const std::function<std::string()>& body) {
  int pipe_ends[2];
  REQUIRE(::pipe(pipe_ends) == 0);
  const pid_t child = ::fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    ::close(pipe_ends[0]);
    const std::string said = body();
    [[maybe_unused]] const auto written = ::write(pipe_ends[1], said.data(), said.size());
    ::_exit(0);
  }
  ::close(pipe_ends[1]);
  std::string said;
  char buffer[4096];
  for (ssize_t n; (n = ::read(pipe_ends[0], buffer, sizeof buffer)) > 0;) said.append(buffer, n);
  ::close(pipe_ends[0]);
  int status = 0;
  ::waitpid(child, &status, 0);
  CHECK(WIFEXITED(status));
  return said;
}

// Runs body in a child process whose address space is limited to `limit` bytes more than the
// test's; returns what body returned.
[[maybe_unused]] std::string in_child_with_memory_limit(std::size_t limit,
                                                        const std::function<std::string()>& body) {
  return in_child([&] {
    std::ifstream status("/proc/self/statm");
    std::size_t pages = 0;
    status >> pages;
    const rlim_t bytes = pages * static_cast<std::size_t>(::sysconf(_SC_PAGESIZE)) + limit;
    const rlimit cap{bytes, bytes};
    ::setrlimit(RLIMIT_AS, &cap);
    return body();
  });
}

// An endless scene: a canvas, then the same triangle line again and again, never held in memory.
class EndlessScene : public std::streambuf {
 public:
  explicit EndlessScene(std::uint64_t triangles) : left_(triangles) {
    setg(header_.data(), header_.data(), header_.data() + header_.size());
  }

 protected:
  int_type underflow() override {
    if (left_ == 0) return traits_type::eof();
    --left_;
    setg(line_.data(), line_.data(), line_.data() + line_.size());
    return traits_type::to_int_type(line_[0]);
  }

 private:
  std::string header_ = "canvas 64 64\n";
  std::string line_ = "tri 0.5 0.25 60 3 7 61.75 10 20 30\n";
  std::uint64_t left_;
};

}  // namespace

#if defined(__SANITIZE_ADDRESS__)
#define TRI_UNDER_ADDRESS_SANITIZER 1  // it reserves terabytes of address space, pads every block
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define TRI_UNDER_ADDRESS_SANITIZER 1
#endif
#endif

TEST_CASE("raster names what it was allocating and the limit to lower when memory runs out",
          "[raster][memory]") {
#ifdef TRI_UNDER_ADDRESS_SANITIZER
  SUCCEED("an address-space limit cannot be set under AddressSanitizer");
#else
  ScratchFolder dir;
  const auto scene = dir.file("huge.scene", "canvas 16384 16384\nline 0 0 5 5\n");
  const std::string said = in_child_with_memory_limit(256 << 20, [&] {
    const Outcome o = raster({"--scene", scene.string(), "--out", (dir / "x.png").string()});
    return std::to_string(o.status) + " " + o.err;
  });
  CHECK(said ==
        "1 raster: error: out of memory while allocating the 16384x16384 canvas (1.0 GiB); lower "
        "the scene's canvas size\n");
  const std::string coverage = in_child_with_memory_limit(256 << 20, [&] {
    const Outcome o = raster({"--algo", "area_cells", "--scene", scene.string(), "--coverage",
                              (dir / "c.pgm").string()});
    return std::to_string(o.status) + " " + o.err;
  });
  CHECK(coverage ==
        "1 raster: error: out of memory while allocating the coverage values of the 16384x16384 "
        "canvas (1.0 GiB); lower the scene's canvas size\n");
  CHECK_FALSE(fs::exists(dir / "x.png"));
  CHECK_FALSE(fs::exists(dir / "c.pgm"));
#endif
}

TEST_CASE("Reading a scene names the primitives read and the limit to lower when memory runs out",
          "[raster][memory]") {
#ifdef TRI_UNDER_ADDRESS_SANITIZER
  SUCCEED("an address-space limit cannot be set under AddressSanitizer");
#else
  const std::string said = in_child_with_memory_limit(64 << 20, [] {
    EndlessScene endless(std::uint64_t{1} << 40);
    std::istream in(&endless);
    try {
      tri::parse_scene(in, "endless", {.max_primitives = std::size_t{1} << 40});
    } catch (const tri::SceneError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  });
  CHECK(std::regex_match(said, std::regex("endless:[0-9]+: out of memory while storing the "
                                          "scene's primitives \\([0-9]+ read, [0-9]+ MiB held\\); "
                                          "lower the number of triangles and lines")));
#endif
}

namespace {

// A field of /proc/self/status in KiB ("VmRSS", "VmHWM").
[[maybe_unused]] long status_kib(const std::string& field) {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);) {
    if (line.starts_with(field + ":")) return std::stol(line.substr(field.size() + 1));
  }
  return -1;
}

// How far this process's resident memory rises above where it was while body runs: in a child
// process that first returns its free memory to the system and resets its peak (VmHWM), so that
// earlier tests count neither way.
[[maybe_unused]] long peak_growth_kib(const std::function<void()>& body) {
  const std::string growth = in_child([&] {
    ::malloc_trim(0);  // memory the test freed earlier would hide new allocations
    std::ofstream("/proc/self/clear_refs") << "5";
    const long before = status_kib("VmRSS");
    body();
    return std::to_string(status_kib("VmHWM") - before);
  });
  return growth.empty() ? -1 : std::stol(growth);
}

}  // namespace

// The figure common/scene.hpp and docs/DESIGN.md state: max_scene_primitives primitives held in
// a vector of 64-byte variants (122 MiB), whose last doubling holds the old 64 MiB while it copies
// them into the new storage. Measured: 128 MiB to read, 129-130 MiB to draw or cover on 64x64.
TEST_CASE(
    "A scene of 2,000,000 primitives takes at most 136 MiB to read and to draw on a small "
    "canvas",
    "[raster][memory]") {
  CHECK(sizeof(tri::ScenePrimitive) == 64);
#ifdef TRI_UNDER_ADDRESS_SANITIZER
  SUCCEED("AddressSanitizer's padding and quarantine are not the program's memory");
#else
  const long reading = peak_growth_kib([] {
    EndlessScene endless(tri::max_scene_primitives);
    std::istream in(&endless);
    const tri::Scene scene = tri::parse_scene(in, "endless");
    if (scene.primitives.size() != tri::max_scene_primitives) ::_exit(1);
  });
  INFO("reading: " << reading / 1024 << " MiB");
  CHECK(reading > 122 * 1024);  // the primitives themselves: 2,000,000 x 64 bytes
  CHECK(reading <= 136 * 1024);

  ScratchFolder dir;
  {
    std::ofstream file(dir / "big.scene", std::ios::binary);
    EndlessScene endless(tri::max_scene_primitives);
    file << &endless;
  }
  for (const auto& form : std::vector<std::vector<std::string>>{
           {"--algo", "fast_spans", "--out", (dir / "x.png").string()},
           {"--algo", "area_cells", "--coverage", (dir / "c.pgm").string()}}) {
    std::vector<std::string> words = form;
    words.emplace_back("--scene");
    words.emplace_back((dir / "big.scene").string());
    const long drawing = peak_growth_kib([&] {
      if (raster(words).status != 0) ::_exit(1);
    });
    INFO(form[1] << ": " << drawing / 1024 << " MiB");
    CHECK(drawing <= 136 * 1024);
  }
#endif
}
