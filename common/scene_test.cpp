#include <catch2/catch.hpp>

#include <array>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <variant>

#include "common/scene.hpp"
#include "tests/support/scratch_folder.hpp"

namespace tri {
namespace {

namespace fs = std::filesystem;

// Catch prints std::array and std::pair, not glm vectors, so those are compared instead.
std::array<int, 4> rgba(Color c) {
  return {c.r, c.g, c.b, c.a};
}
std::pair<double, double> xy(glm::dvec2 p) {
  return {p.x, p.y};
}

Scene parse(const std::string& text) {
  std::istringstream in(text);
  return parse_scene(in, "test.scene");
}

// The message of the SceneError that parsing throws, or a note that it did not throw.
std::string error_of(const std::string& text) {
  try {
    parse(text);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no SceneError)";
}

// An endless stream of one repeated text that counts how many bytes were taken from it.
class EndlessText : public std::streambuf {
 public:
  explicit EndlessText(std::string prefix, std::string unit)
      : prefix_(std::move(prefix)), unit_(std::move(unit)) {}
  std::uint64_t bytes_read() const noexcept { return bytes_read_; }

 protected:
  int_type underflow() override {
    chunk_.clear();
    if (!prefix_.empty()) std::swap(chunk_, prefix_);
    while (chunk_.size() < 4096) chunk_ += unit_;
    bytes_read_ += chunk_.size();
    setg(chunk_.data(), chunk_.data(), chunk_.data() + chunk_.size());
    return traits_type::to_int_type(chunk_[0]);
  }

 private:
  std::string prefix_, unit_, chunk_;
  std::uint64_t bytes_read_ = 0;
};

}  // namespace

TEST_CASE("A UTF-8 byte order mark at the start of a scene is accepted, elsewhere it is named",
          "[common][scene][limits]") {
  const Scene scene = parse(
      "\xEF\xBB\xBF"
      "canvas 4 3\ntri 0 0 3 0 0 2\n");
  CHECK(scene.width == 4);
  CHECK(scene.primitives.size() == 1);
  CHECK(parse("\xEF\xBB\xBF# comment first\ncanvas 4 3\n").height == 3);
  CHECK(error_of("canvas 4 3\n\xEF\xBB\xBFtri 0 0 3 0 0 2\n") ==
        "test.scene:2: unknown directive '\\xEF\\xBB\\xBFtri' (expected canvas, tri or line)");
}

TEST_CASE("A line at the length limit is read, a longer one is refused naming the limit and line",
          "[common][scene][limits]") {
  const std::string comment = "#" + std::string(max_scene_line_bytes - 1, 'c');
  CHECK(parse("canvas 4 4\n" + comment + "\n").width == 4);
  CHECK(parse("canvas 4 4\n" + comment).width == 4);  // the same line without a final newline
  CHECK(error_of("canvas 4 4\n" + comment + "c\n") ==
        "test.scene:2: line longer than 65536 bytes, the limit of a scene line");
}

TEST_CASE("An endless line is refused after reading about the limit, quickly",
          "[common][scene][limits]") {
  EndlessText text("canvas 4 4\n# ", "zzzzzzzz");
  std::istream in(&text);
  const auto start = std::chrono::steady_clock::now();
  CHECK_THROWS_WITH(parse_scene(in, "endless"),
                    "endless:2: line longer than 65536 bytes, the limit of a scene line");
  CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(1));
  CHECK(text.bytes_read() < max_scene_line_bytes + 16 * 1024);
}

TEST_CASE("A scene of more primitives than the limit is refused at the first one too many",
          "[common][scene][limits]") {
  // The documented limit, 2,000,000, takes half a minute under the sanitizers: a smaller one here.
  const SceneLimits limits{max_scene_line_bytes, 1000};
  EndlessText text("canvas 4 4\n", "line 0 0 1 1\ntri 0 0 1 0 0 1\n");
  std::istream in(&text);
  CHECK_THROWS_WITH(parse_scene(in, "endless", limits),
                    "endless:1002: more than 1000 primitives, the limit of a scene");
  std::string exactly = "canvas 4 4\n";
  for (int i = 0; i < 1000; ++i) exactly += "line 0 0 1 1\n";
  std::istringstream full(exactly);
  CHECK(parse_scene(full, "full", limits).primitives.size() == 1000);
  CHECK(SceneLimits{}.max_primitives == 2'000'000);
  CHECK(SceneLimits{}.max_line_bytes == 65'536);
}

TEST_CASE("Words of a scene appear in messages short and escaped", "[common][scene][errors]") {
  CHECK(error_of(std::string("canvas 4 4\nsq\0uare\n", 19)) ==
        "test.scene:2: unknown directive 'sq\\x00uare' (expected canvas, tri or line)");
  CHECK(error_of("canvas 4 4\n\x1b]0;pwned\x07 1\n") ==
        "test.scene:2: unknown directive '\\x1B]0;pwned\\x07' (expected canvas, tri or line)");
  CHECK(error_of("canvas 4 4\ntri 0 0 1 1 2 \xff\n") ==
        "test.scene:2: expected a decimal number for y2, got '\\xFF'");
  const std::string huge(60'000, '9');
  CHECK(error_of("canvas 4 4\nline 0 0 1 " + huge + "x\n") ==
        "test.scene:2: expected a decimal number for y1, got '" + std::string(32, '9') +
            "...(60001 bytes)'");
}

TEST_CASE("A full scene parses with comments, blank lines, tabs, CRLF and optional colours",
          "[common][scene]") {
  const std::string text =
      "# A scene that uses every feature of the format.\r\n"
      "\r\n"
      "canvas\t200  150 10 20 30   # background colour\r\n"
      "   \t\r\n"
      "tri 10 70 50 160 70 80\r\n"
      "tri -1.5 2.25 1e3 -2.5E-1 .5 7. 255 0 128\r\n"
      "\tline 0 0 199 149 0 255 0#comment right after a value\r\n"
      "line -1073741824 1073741824 3e2 -0.0\n"
      "# the last line has no line break\n"
      "tri 1 1 2 2 3 1 1 2 3";
  const Scene scene = parse(text);
  CHECK(scene.width == 200);
  CHECK(scene.height == 150);
  CHECK(rgba(scene.background) == std::array{10, 20, 30, 255});
  REQUIRE(scene.primitives.size() == 5);

  const auto& first = std::get<SceneTriangle>(scene.primitives[0]);
  CHECK(xy(first.vertices[0]) == std::pair<double, double>(10, 70));
  CHECK(xy(first.vertices[1]) == std::pair<double, double>(50, 160));
  CHECK(xy(first.vertices[2]) == std::pair<double, double>(70, 80));
  CHECK(rgba(first.color) == rgba(colors::white));

  const auto& second = std::get<SceneTriangle>(scene.primitives[1]);
  CHECK(xy(second.vertices[0]) == std::pair<double, double>(-1.5, 2.25));
  CHECK(xy(second.vertices[1]) == std::pair<double, double>(1000.0, -0.25));
  CHECK(xy(second.vertices[2]) == std::pair<double, double>(0.5, 7.0));
  CHECK(rgba(second.color) == std::array{255, 0, 128, 255});

  const auto& third = std::get<SceneLine>(scene.primitives[2]);
  CHECK(xy(third.ends[0]) == std::pair<double, double>(0, 0));
  CHECK(xy(third.ends[1]) == std::pair<double, double>(199, 149));
  CHECK(rgba(third.color) == rgba(colors::green));

  const auto& fourth = std::get<SceneLine>(scene.primitives[3]);
  CHECK(xy(fourth.ends[0]) == std::pair<double, double>(-1073741824.0, 1073741824.0));
  CHECK(xy(fourth.ends[1]) == std::pair<double, double>(300.0, 0.0));
  CHECK(rgba(fourth.color) == rgba(colors::white));

  const auto& fifth = std::get<SceneTriangle>(scene.primitives[4]);
  CHECK(xy(fifth.vertices[2]) == std::pair<double, double>(3, 1));
  CHECK(rgba(fifth.color) == std::array{1, 2, 3, 255});
}

TEST_CASE("A scene without a background colour is black and may have no primitives",
          "[common][scene]") {
  const Scene scene = parse("canvas 1 16384\n");
  CHECK(scene.width == 1);
  CHECK(scene.height == 16384);
  CHECK(rgba(scene.background) == rgba(colors::black));
  CHECK(scene.primitives.empty());
}

TEST_CASE("A coordinate too small for a double reads as zero, not as out of range",
          "[common][scene]") {
  const Scene scene = parse("canvas 10 10\ntri 1e-400 -1e-400 4.9e-324 0 1 1\n");
  const auto& triangle = std::get<SceneTriangle>(scene.primitives.at(0));
  CHECK(xy(triangle.vertices[0]) == std::pair<double, double>(0.0, 0.0));
  CHECK(triangle.vertices[1].x > 0.0);  // the smallest subnormal is still representable
  CHECK(triangle.vertices[1].x < 1e-300);
}

TEST_CASE("Coordinates of exactly plus or minus 2^30 are accepted", "[common][scene]") {
  const Scene scene =
      parse("canvas 10 10\ntri 1073741824 -1073741824 1073741824.0 0 -1.073741824e9 0\n");
  const auto& triangle = std::get<SceneTriangle>(scene.primitives.at(0));
  CHECK(xy(triangle.vertices[0]) == std::pair<double, double>(1073741824.0, -1073741824.0));
  CHECK(triangle.vertices[2].x == -1073741824.0);
}

TEST_CASE("Each scene error is one line naming the source, the line and the problem",
          "[common][scene][errors]") {
  struct Case {
    const char* text;
    const char* message;
  };
  const Case cases[] = {
      // Structure.
      {"", "test.scene: missing 'canvas W H' directive"},
      {"# only a comment\n\n", "test.scene: missing 'canvas W H' directive"},
      {"tri 0 0 1 1 2 0\ncanvas 10 10\n", "test.scene:1: 'tri' before the 'canvas' directive"},
      {"\n# c\nline 0 0 1 1\ncanvas 10 10\n", "test.scene:3: 'line' before the 'canvas' directive"},
      {"canvas 10 10\ncanvas 20 20\n", "test.scene:2: a scene has exactly one 'canvas' directive"},
      {"canvas 10 10\r\n\r\n\r\nsquare 1 2 3\r\n",
       "test.scene:4: unknown directive 'square' (expected canvas, tri or line)"},
      {"canvas 10 10\nTri 0 0 1 1 2 0\n",
       "test.scene:2: unknown directive 'Tri' (expected canvas, tri or line)"},
      // Value counts.
      {"canvas 10\n", "test.scene:1: expected 'canvas W H [r g b]', got 1 value"},
      {"canvas 10 10 255\n", "test.scene:1: expected 'canvas W H [r g b]', got 3 values"},
      {"canvas 10 10 1 2 3 4\n", "test.scene:1: expected 'canvas W H [r g b]', got 6 values"},
      {"canvas 10 10\ntri 0 0 1 1 2\n",
       "test.scene:2: expected 'tri x0 y0 x1 y1 x2 y2 [r g b]', got 5 values"},
      {"canvas 10 10\ntri 0 0 1 1 2 0 255\n",
       "test.scene:2: expected 'tri x0 y0 x1 y1 x2 y2 [r g b]', got 7 values"},
      {"canvas 10 10\ntri\n",
       "test.scene:2: expected 'tri x0 y0 x1 y1 x2 y2 [r g b]', got 0 values"},
      {"canvas 10 10\nline 0 0 1\n",
       "test.scene:2: expected 'line x0 y0 x1 y1 [r g b]', got 3 values"},
      // Malformed numbers.
      {"canvas 10 10\ntri 0 0 1 1 2 x\n",
       "test.scene:2: expected a decimal number for y2, got 'x'"},
      {"canvas 10 10\ntri 1.2.3 0 1 1 2 0\n",
       "test.scene:2: expected a decimal number for x0, got '1.2.3'"},
      {"canvas 10 10\ntri 0 0 1,5 1 2 0\n",
       "test.scene:2: expected a decimal number for x1, got '1,5'"},
      {"canvas 10 10\nline 0 0 0x10 1\n",
       "test.scene:2: expected a decimal number for x1, got '0x10'"},
      {"canvas 10 10\nline 0 0 1 1e\n", "test.scene:2: expected a decimal number for y1, got '1e'"},
      {"canvas 10.5 10\n", "test.scene:1: expected a whole number for canvas width, got '10.5'"},
      {"canvas ten 10\n", "test.scene:1: expected a whole number for canvas width, got 'ten'"},
      // Canvas size.
      {"canvas 0 10\n", "test.scene:1: canvas width 0 is outside 1..16384"},
      {"canvas 10 0\n", "test.scene:1: canvas height 0 is outside 1..16384"},
      {"canvas -5 10\n", "test.scene:1: canvas width -5 is outside 1..16384"},
      {"canvas 16385 10\n", "test.scene:1: canvas width 16385 is outside 1..16384"},
      {"canvas 10 16385\n", "test.scene:1: canvas height 16385 is outside 1..16384"},
      {"canvas 99999999999 10\n", "test.scene:1: canvas width 99999999999 is outside 1..16384"},
      // Colours.
      {"canvas 10 10 0 0 256\n", "test.scene:1: blue 256 is outside 0..255"},
      {"canvas 10 10\ntri 0 0 1 1 2 0 256 0 0\n", "test.scene:2: red 256 is outside 0..255"},
      {"canvas 10 10\ntri 0 0 1 1 2 0 0 -1 0\n", "test.scene:2: green -1 is outside 0..255"},
      {"canvas 10 10\nline 0 0 1 1 0 0 1000\n", "test.scene:2: blue 1000 is outside 0..255"},
      {"canvas 10 10\nline 0 0 1 1 0 0.5 0\n",
       "test.scene:2: expected a whole number for green, got '0.5'"},
      // Non-finite coordinates.
      {"canvas 10 10\ntri NaN 0 1 1 2 0\n",
       "test.scene:2: x0 is NaN; coordinates must be finite numbers"},
      {"canvas 10 10\ntri 0 nan 1 1 2 0\n",
       "test.scene:2: y0 is NaN; coordinates must be finite numbers"},
      {"canvas 10 10\ntri 0 0 -nan 1 2 0\n",
       "test.scene:2: x1 is NaN; coordinates must be finite numbers"},
      {"canvas 10 10\ntri 0 0 1 inf 2 0\n",
       "test.scene:2: y1 is infinite; coordinates must be finite numbers"},
      {"canvas 10 10\ntri 0 0 1 1 -inf 0\n",
       "test.scene:2: x2 is infinite; coordinates must be finite numbers"},
      {"canvas 10 10\nline 0 0 1 infinity\n",
       "test.scene:2: y1 is infinite; coordinates must be finite numbers"},
      {"canvas 10 10\nline 0 0 1 -Infinity\n",
       "test.scene:2: y1 is infinite; coordinates must be finite numbers"},
      // Coordinates beyond the limits.
      {"canvas 10 10\ntri 1073741825 0 1 1 2 0\n",
       "test.scene:2: x0 1073741825 is outside ±2^30 (1073741824)"},
      {"canvas 10 10\ntri 0 -1073741824.5 1 1 2 0\n",
       "test.scene:2: y0 -1073741824.5 is outside ±2^30 (1073741824)"},
      {"canvas 10 10\nline 0 0 1e10 0\n", "test.scene:2: x1 1e10 is outside ±2^30 (1073741824)"},
      {"canvas 10 10\nline 0 0 0 1e400\n", "test.scene:2: y1 1e400 is outside ±2^30 (1073741824)"},
      {"canvas 10 10\nline -1e400 0 0 0\n",
       "test.scene:2: x0 -1e400 is outside ±2^30 (1073741824)"},
  };
  for (const Case& c : cases) {
    INFO("scene text: " << c.text);
    CHECK(error_of(c.text) == c.message);
  }
}

TEST_CASE("A scene with an error returns nothing: the first error is thrown",
          "[common][scene][errors]") {
  // Valid primitives before the problem do not come back as a partial scene.
  const std::string text =
      "canvas 10 10\n"
      "tri 0 0 5 0 0 5\n"
      "line 0 0 9 9\n"
      "tri 0 0 5 0 0 nan\n"
      "bogus\n";
  std::istringstream in(text);
  CHECK_THROWS_AS(parse_scene(in, "partial.scene"), SceneError);
  CHECK(error_of(text) == "test.scene:4: y2 is NaN; coordinates must be finite numbers");
}

TEST_CASE("Scene errors are runtime errors, so callers may catch either",
          "[common][scene][errors]") {
  CHECK_THROWS_AS(parse("canvas 0 0\n"), std::runtime_error);
}

TEST_CASE("load_scene reads a scene file and names the file in its errors",
          "[common][scene][files]") {
  const testing::ScratchFolder scratch("load_scene");
  const fs::path& folder = scratch.path();

  const fs::path good = folder / "good.scene";
  std::ofstream(good) << "canvas 20 10 1 2 3\ntri 0 0 19 0 0 9 255 0 0\n";
  const Scene scene = load_scene(good);
  CHECK(scene.width == 20);
  CHECK(scene.height == 10);
  REQUIRE(scene.primitives.size() == 1);
  CHECK(rgba(std::get<SceneTriangle>(scene.primitives[0]).color) == rgba(colors::red));

  const fs::path bad = folder / "bad.scene";
  std::ofstream(bad) << "canvas 20 10\n\nline 0 0 1\n";
  CHECK_THROWS_WITH(load_scene(bad),
                    bad.string() + ":3: expected 'line x0 y0 x1 y1 [r g b]', got 3 values");

  const fs::path missing = folder / "missing.scene";
  CHECK_THROWS_AS(load_scene(missing), SceneError);
  CHECK_THROWS_WITH(load_scene(missing),
                    missing.string() + ": cannot open the scene file: No such file or directory");

  // A folder opens on some systems but cannot be read: still an error naming it and the reason.
  CHECK_THROWS_AS(load_scene(folder), SceneError);
  CHECK_THROWS_WITH(load_scene(folder),
                    folder.string() + ": cannot read the scene file: Is a directory");

}

}  // namespace tri
