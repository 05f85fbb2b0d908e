// The fuzz targets' checks, run in every test run with the normal compiler: on every seed of the
// corpus, on every past finding (one named TEST_CASE each), and on deliberately broken inputs so
// the checks are known to catch what they claim to.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include "fuzz/rasterizer_check.hpp"
#include "fuzz/rasterizer_input.hpp"
#include "fuzz/rasterizer_seeds.hpp"
#include "fuzz/regressions/corpus_files.hpp"
#include "fuzz/scene_parser_check.hpp"
#include "measure/registry.hpp"

namespace tri::fuzz {
namespace {

namespace fs = std::filesystem;

// The files of one target's corpus, sorted so failures are listed in a stable order; a corpus
// has at least 25 seeds (required).
std::vector<fs::path> corpus_files(const std::string& target) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(corpus_folder / target)) {
    if (entry.is_regular_file()) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  REQUIRE(files.size() >= 25);
  return files;
}

// What fuzz_rasterizers checks, applied with every registered algorithm instead of the one the
// input's first byte picks, so a seed or finding guards each algorithm.
void require_rasterizer_checks_hold(std::span<const std::uint8_t> bytes) {
  const RasterizerInput input = decode_rasterizer_input(bytes);
  for (const TriangleAlgorithm& algorithm : registered_algorithms()) {
    INFO("algorithm " << algorithm.name);
    CHECK(check_rasterizer(algorithm, input) == Findings{});
  }
}

// What fuzz_scene_parser checks; returns the outcome for further assertions.
ParseOutcome require_scene_checks_hold(std::string_view text) {
  ParseOutcome outcome = check_scene_parser(text);
  CHECK(outcome.findings == Findings{});
  return outcome;
}

std::string as_text(const std::vector<std::uint8_t>& bytes) {
  return {bytes.begin(), bytes.end()};
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// The seed corpus.

TEST_CASE("Every scene seed keeps the parser's contract, and its name says whether it parses",
          "[fuzz][corpus]") {
  for (const fs::path& file : corpus_files("fuzz_scene_parser")) {
    INFO("seed " << file.filename().string());
    const ParseOutcome outcome = require_scene_checks_hold(as_text(read_bytes(file)));
    const std::string name = file.filename().string();
    if (name.starts_with("valid_")) CHECK(outcome.parsed);
    if (name.starts_with("error_")) CHECK_FALSE(outcome.error.empty());
  }
}

TEST_CASE("The scene seeds hit every kind of parser error", "[fuzz][corpus]") {
  std::string messages;
  for (const fs::path& file : corpus_files("fuzz_scene_parser")) {
    messages += check_scene_parser(as_text(read_bytes(file))).error + "\n";
  }
  for (const char* kind :
       {"expected a decimal number", "is NaN", "is infinite", "is outside ±2^30",
        "expected a whole number", "is outside 1..16384", "is outside 0..255", "expected 'tri",
        "expected 'line", "exactly one 'canvas'", "before the 'canvas' directive",
        "unknown directive", "missing 'canvas W H' directive"}) {
    INFO("error kind: " << kind);
    CHECK(messages.find(kind) != std::string::npos);
  }
}

TEST_CASE("The scene seeds reach the parser's limits through the fuzz limits", "[fuzz][corpus]") {
  std::string messages;
  for (const fs::path& file : corpus_files("fuzz_scene_parser")) {
    messages += check_scene_parser(as_text(read_bytes(file))).small_limits_error + "\n";
  }
  CHECK_THAT(messages, Catch::Contains("more than 8 primitives, the limit of a scene"));
  CHECK_THAT(messages, Catch::Contains("line longer than 64 bytes"));
}

TEST_CASE("Every rasterizer seed keeps the checks with every registered algorithm",
          "[fuzz][corpus]") {
  for (const fs::path& file : corpus_files("fuzz_rasterizers")) {
    INFO("seed " << file.filename().string());
    require_rasterizer_checks_hold(read_bytes(file));
  }
}

TEST_CASE("The rasterizer seeds in the repository are the ones fuzz_seed_writer writes",
          "[fuzz][corpus]") {
  for (const NamedSeed& seed : rasterizer_seeds()) {
    INFO("seed " << seed.name << " (rewrite the corpus with fuzz_seed_writer)");
    CHECK(read_bytes(corpus_folder / "fuzz_rasterizers" / seed.name) == seed.bytes);
  }
}

TEST_CASE("The rasterizer seeds reach the oracle comparison, refusals and the batch path",
          "[fuzz][corpus]") {
  int on_grid = 0;
  int refused = 0;
  int several = 0;
  for (const NamedSeed& seed : rasterizer_seeds()) {
    const RasterizerInput input = decode_rasterizer_input(seed.bytes);
    several += input.triangles.size() > 1;
    for (const SceneTriangle& t : input.triangles) {
      on_grid += on_subpixel_grid(t.vertices);
      refused += validate_triangle(t.vertices) != DrawResult::drawn;
    }
  }
  CHECK(on_grid >= 20);
  CHECK(refused >= 7);
  CHECK(several == 2);
}

// ---------------------------------------------------------------------------------------------
// The input layout the corpus depends on.

TEST_CASE("An input decodes to the algorithm, canvas and triangle its bytes spell",
          "[fuzz][layout]") {
  // Selector 7, width 63 + 1, height 64 % 64 + 1; one interesting triangle in colour 10 20 30.
  const std::vector<std::uint8_t> bytes{7,  63,   64,  1, 10, 20, 30,  //
                                        1,  0xFF, 128,                 // 2^30 - 1 + 1/2
                                        0,  3,    0,                   // 3
                                        15, 0,    0,                   // NaN
                                        5,  0,    1,                   // 2^24 + 1 + 1/256
                                        2,  0,    0,                   // -2^30
                                        0,  0x80, 0};                  // -128
  const RasterizerInput input = decode_rasterizer_input(bytes);
  CHECK(input.algorithm_selector == 7);
  CHECK(input.width == 64);
  CHECK(input.height == 1);
  REQUIRE(input.triangles.size() == 1);
  const SceneTriangle& t = input.triangles[0];
  CHECK(std::array<int, 4>{t.color.r, t.color.g, t.color.b, t.color.a} ==
        std::array<int, 4>{10, 20, 30, 255});
  CHECK(t.vertices[0].x == 1073741823.5);
  CHECK(t.vertices[0].y == 3.0);
  CHECK(std::isnan(t.vertices[1].x));
  CHECK(t.vertices[1].y == 16777217.0 + 1.0 / 256);
  CHECK(t.vertices[2].x == -1073741824.0);
  CHECK(t.vertices[2].y == -128.0);
}

TEST_CASE("Raw doubles are read little-endian, and missing bytes read as zero", "[fuzz][layout]") {
  // 1.0 is 0x3FF0000000000000; the input ends after x0, so the other coordinates are 0.
  const std::vector<std::uint8_t> bytes{0, 0, 0, 0, 1, 2, 3, 0, 0, 0, 0, 0, 0, 0xF0, 0x3F};
  const RasterizerInput input = decode_rasterizer_input(bytes);
  CHECK(input.width == 1);
  REQUIRE(input.triangles.size() == 1);
  CHECK(input.triangles[0].vertices[0].x == 1.0);
  CHECK(input.triangles[0].vertices[2].y == 0.0);
}

TEST_CASE("An empty input is one triangle at the origin on a 1x1 canvas", "[fuzz][layout]") {
  const RasterizerInput input = decode_rasterizer_input({});
  CHECK(input.width == 1);
  CHECK(input.height == 1);
  REQUIRE(input.triangles.size() == 1);
  CHECK(input.triangles[0].vertices[1].x == 0.0);
}

TEST_CASE("Every byte left starts a triangle, up to four", "[fuzz][layout]") {
  RasterizerInputWriter writer(0, 8, 8);
  for (int i = 0; i < 6; ++i) writer.interesting({}, colors::white);
  std::vector<std::uint8_t> bytes = writer.bytes();
  CHECK(decode_rasterizer_input(bytes).triangles.size() == 4);
  bytes.resize(3 + 22 + 1);  // one whole record and one byte of the next
  CHECK(decode_rasterizer_input(bytes).triangles.size() == 2);
}

TEST_CASE("Interesting values up to 2^31 stay exactly on the 1/256 grid", "[fuzz][layout]") {
  for (int base = 0; base < static_cast<int>(Base::count); ++base) {
    const double value = base_value(static_cast<Base>(base));
    if (!std::isfinite(value) || std::abs(value) > 2147483648.0) continue;
    if (std::floor(value * 256) != value * 256) continue;  // almost_half and subnormal
    INFO("base " << base);
    const double built = interesting_value({static_cast<Base>(base), -77, 3});
    CHECK(built * 256 == value * 256 - 77 * 256 + 3);
  }
}

// ---------------------------------------------------------------------------------------------
// The checks catch what they claim to (each broken algorithm must be reported).

namespace {

namespace broken {

void writes_outside(Canvas& canvas, const Triangle&, Color color) {
  canvas.put_pixel(-1, 0, color);
}
void paints_in_another_colour(Canvas& canvas, const Triangle&, Color) {
  canvas.put_pixel(0, 0, Color{1, 2, 3, 255});
}
void draws_one_pixel(Canvas& canvas, const Triangle&, Color color) {
  canvas.put_pixel(0, 0, color);
}
void draws_nothing(Canvas&, const Triangle&, Color) {}
void batch_draws_nothing(Canvas&, std::span<const SceneTriangle>) {}

}  // namespace broken

RasterizerInput triangle_on_8x8(const Triangle& t) {
  return {0, 8, 8, {SceneTriangle{t, colors::white}}};
}

// What the checks find when a broken algorithm (its rule, its draw and, when given, its batch
// draw) draws one triangle on an 8x8 canvas.
Findings findings_of(std::string_view name, CoverageRule rule, DrawTriangleFunction draw,
                     const Triangle& triangle, DrawBatchFunction draw_batch = nullptr) {
  const TriangleAlgorithm algorithm{.name = name,
                                    .chapter = "test",
                                    .rule = rule,
                                    .summary = "",
                                    .draw = draw,
                                    .draw_batch = draw_batch};
  return check_rasterizer(algorithm, triangle_on_8x8(triangle));
}

}  // namespace

TEST_CASE("The rasterizer checks report writes outside the canvas", "[fuzz][checks]") {
  const Findings findings = findings_of("outside", CoverageRule::approximate,
                                        broken::writes_outside, {{{1, 1}, {6, 1}, {1, 6}}});
  REQUIRE(findings.size() == 1);
  CHECK_THAT(findings[0], Catch::Contains("1 writes outside the canvas"));
}

TEST_CASE("The rasterizer checks report a foreign colour", "[fuzz][checks]") {
  const Findings findings =
      findings_of("colour", CoverageRule::approximate, broken::paints_in_another_colour,
                  {{{1, 1}, {6, 1}, {1, 6}}});
  REQUIRE(findings.size() == 2);
  CHECK_THAT(findings[0], Catch::Contains("neither the background nor the triangle's 1: (0, 0)"));
  CHECK_THAT(findings[1], Catch::Contains("counted as written"));
}

TEST_CASE("The rasterizer checks report a top-left algorithm that differs from the oracle",
          "[fuzz][checks]") {
  // (1,1) (3,1) (1,3): the oracle covers (1,2) alone; the centres on the bottom edge and on the
  // hypotenuse belong to neither a top nor a left edge.
  const Findings findings = findings_of("nothing", CoverageRule::top_left, broken::draws_nothing,
                                        {{{1, 1}, {3, 1}, {1, 3}}});
  REQUIRE(findings.size() == 1);
  CHECK_THAT(findings[0], Catch::Contains("missed 1: (1, 2); extra 0:"));
}

TEST_CASE("The rasterizer checks compare with the oracle only on the 1/256 grid",
          "[fuzz][checks]") {
  CHECK(findings_of("nothing", CoverageRule::top_left, broken::draws_nothing,
                    {{{1, 1}, {3.001, 1}, {1, 3}}})
            .empty());
  CHECK(findings_of("nothing", CoverageRule::approximate, broken::draws_nothing,
                    {{{1, 1}, {3, 1}, {1, 3}}})
            .empty());
}

TEST_CASE("The rasterizer checks report a batch that differs from drawing one by one",
          "[fuzz][checks]") {
  const Findings findings = findings_of("batch", CoverageRule::approximate, broken::draws_one_pixel,
                                        {{{1, 1}, {6, 1}, {1, 6}}}, broken::batch_draws_nothing);
  REQUIRE(findings.size() == 1);
  CHECK_THAT(findings[0], Catch::Contains("pixels differ from drawing them one by one 1: (0, 0)"));
}

TEST_CASE("A refused triangle never reaches the algorithm, so nothing is reported",
          "[fuzz][checks]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK(findings_of("outside", CoverageRule::approximate, broken::writes_outside,
                    {{{nan, 1}, {6, 1}, {1, 6}}})
            .empty());
}

TEST_CASE("The scene contract check reports more primitives than the limits allow",
          "[fuzz][checks]") {
  Scene scene;
  scene.width = scene.height = 8;
  for (int i = 0; i < 9; ++i) scene.primitives.emplace_back(SceneLine{{{{0, i}, {7, i}}}});
  CHECK(check_scene_contract(scene) == Findings{});
  const Findings findings = check_scene_contract(scene, fuzz_scene_limits);
  REQUIRE(findings.size() == 1);
  CHECK_THAT(findings[0], Catch::Contains("9 primitives, more than the limit 8"));
}

TEST_CASE("The scene contract check reports a bad canvas and coordinates beyond the limits",
          "[fuzz][checks]") {
  Scene scene;
  scene.width = 0;
  scene.height = 16385;
  scene.primitives.emplace_back(SceneTriangle{{{{0, 0}, {1, 0}, {0, 2147483648.0}}}});
  scene.primitives.emplace_back(
      SceneLine{{{{0, 0}, {std::numeric_limits<double>::infinity(), 0}}}});
  const Findings findings = check_scene_contract(scene);
  REQUIRE(findings.size() == 4);
  CHECK_THAT(findings[0], Catch::Contains("0x16385 canvas"));
  CHECK_THAT(findings[1], Catch::Contains("validate_triangle refuses"));
  CHECK_THAT(findings[2], Catch::Contains("primitive 0"));
  CHECK_THAT(findings[3], Catch::Contains("primitive 1"));
}

// ---------------------------------------------------------------------------------------------
// Findings of past fuzzing runs, one named TEST_CASE each (see README.md).

}  // namespace tri::fuzz
