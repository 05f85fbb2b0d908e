#include <algorithm>
#include <catch2/catch.hpp>
#include <cstring>
#include <iterator>
#include <numeric>
#include <vector>

#include "measure/child_process.hpp"
#include "measure/error_metrics.hpp"
#include "measure/peers/llvmpipe_canvas.hpp"
#include "measure/peers/llvmpipe_peer.hpp"
#include "measure/registry.hpp"
#include "measure/render_scene.hpp"
#include "measure/scene_generators.hpp"
#include "tests/peers/peer_test_support.hpp"

using tri::LlvmpipeCanvas;
using tri::peers_test::oracle_counts;

// Mesa is only ever touched in child processes here, as in the benchmark: a process that has
// started llvmpipe's threads cannot fork a child that uses Mesa again (its locks are copied held).
namespace {

// llvmpipe's write counts of the triangles, drawn in a child process.
std::vector<std::uint32_t> llvmpipe_counts_in_child(
    int width, int height, std::span<const tri::SceneTriangle> triangles,
    LlvmpipeCanvas::Viewport viewport = LlvmpipeCanvas::Viewport::guard_band) {
  const std::string bytes = tri::run_in_child_process([&] {
    const auto counts = tri::llvmpipe_write_counts(width, height, triangles, viewport).counts;
    return std::string(reinterpret_cast<const char*>(counts.data()),
                       counts.size() * sizeof(std::uint32_t));
  });
  std::vector<std::uint32_t> counts(bytes.size() / sizeof(std::uint32_t));
  std::memcpy(counts.data(), bytes.data(), counts.size() * sizeof(std::uint32_t));
  return counts;
}

// The scene turned upside down: pixel row j becomes row height - 1 - j.
std::vector<tri::SceneTriangle> mirrored(std::span<const tri::SceneTriangle> triangles,
                                         int height) {
  std::vector<tri::SceneTriangle> out(triangles.begin(), triangles.end());
  for (auto& t : out) {
    for (auto& v : t.vertices) v.y = (height - 1) - v.y;
  }
  return out;
}

std::vector<std::uint32_t> rows_flipped(const std::vector<std::uint32_t>& counts, int width,
                                        int height) {
  std::vector<std::uint32_t> out(counts.size());
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) out[y * width + x] = counts[(height - 1 - y) * width + x];
  }
  return out;
}

}  // namespace

TEST_CASE("llvmpipe draws through OSMesa with the canvas's coordinates", "[peers][llvmpipe]") {
  const std::string renderer = tri::run_in_child_process(
      [] { return LlvmpipeCanvas(8, 8, LlvmpipeCanvas::Pixels::write_counts).renderer(); });
  CHECK(renderer.starts_with("llvmpipe"));
  // A square from (1, 1) to (6, 6) in two triangles: 5x5 pixels whatever the tie rule, and
  // each pixel exactly once where the two halves meet.
  const std::vector<tri::SceneTriangle> square{{{{{1, 1}, {6, 1}, {1, 6}}}, tri::colors::white},
                                               {{{{6, 1}, {6, 6}, {1, 6}}}, tri::colors::white}};
  const auto counts = llvmpipe_counts_in_child(8, 8, square);
  REQUIRE(counts.size() == 64);
  CHECK(std::accumulate(counts.begin(), counts.end(), 0u) == 25);
  CHECK(std::count(counts.begin(), counts.end(), 1u) == 25);
  // llvmpipe keeps the left column and the bottom row; the oracle the left and the top.
  CHECK(counts[1 * 8 + 1] == 1);
  CHECK(counts[5 * 8 + 5] == 1);
  CHECK(counts[6 * 8 + 1] == 0);
  CHECK(counts[1 * 8 + 6] == 0);
  CHECK(oracle_counts(8, 8, square).counts[6 * 8 + 1] == 1);
}

TEST_CASE("llvmpipe's picture has each triangle's colour where it is the only one",
          "[peers][llvmpipe]") {
  struct Tally {
    std::size_t disagreements = 0, red = 0, blue = 0;
  };
  const Tally tally = tri::run_in_child<Tally>([] {
    const tri::Color red{255, 0, 0, 255}, blue{0, 0, 255, 255};
    const std::vector<tri::SceneTriangle> two{{{{{2, 2}, {30, 2}, {2, 20}}}, red},
                                              {{{{40, 10}, {60, 10}, {50, 40}}}, blue}};
    LlvmpipeCanvas canvas(64, 48, LlvmpipeCanvas::Pixels::rgba8);
    canvas.upload(two);
    canvas.draw();
    const auto counts = tri::llvmpipe_write_counts(64, 48, two).counts;
    Tally t;
    for (int y = 0; y < 48; ++y) {
      for (int x = 0; x < 64; ++x) {
        const tri::Color c = canvas.pixel(x, y);
        t.disagreements += (c == red || c == blue) != (counts[y * 64 + x] > 0);
        t.red += c == red;
        t.blue += c == blue;
      }
    }
    return t;
  });
  CHECK(tally.disagreements == 0);
  CHECK(tally.red > 0);
  CHECK(tally.blue > 0);
}

TEST_CASE("llvmpipe is exact with the tie rule mirrored: its pixels are the oracle's upside down",
          "[peers][llvmpipe]") {
  using Kind = tri::SceneRecipe::Kind;
  std::uint64_t seed = 70;
  for (const Kind kind : {Kind::random, Kind::slivers, Kind::fan, Kind::jittered_grid}) {
    for (const int grid_bits : {0, 4, 8}) {
      const tri::Scene scene = tri::peers_test::small_scene(kind, grid_bits, ++seed);
      const auto triangles = tri::scene_triangles(scene);
      CAPTURE(static_cast<int>(kind), grid_bits);
      const auto drawn = llvmpipe_counts_in_child(scene.width, scene.height, triangles);
      const auto truth =
          oracle_counts(scene.width, scene.height, mirrored(triangles, scene.height));
      CHECK(drawn == rows_flipped(truth.counts, scene.width, scene.height));
    }
  }
}

TEST_CASE("With a viewport of just the buffer, llvmpipe's clipping moves border triangles' pixels",
          "[peers][llvmpipe]") {
  const tri::Scene scene = tri::peers_test::small_scene(tri::SceneRecipe::Kind::random, 0, 71);
  const auto triangles = tri::scene_triangles(scene);
  const auto inside_the_canvas = [&](const tri::SceneTriangle& t) {
    return std::all_of(t.vertices.begin(), t.vertices.end(), [&](const auto& v) {
      return v.x >= 0 && v.y >= 0 && v.x <= scene.width - 1 && v.y <= scene.height - 1;
    });
  };
  std::vector<tri::SceneTriangle> inside;
  std::copy_if(triangles.begin(), triangles.end(), std::back_inserter(inside), inside_the_canvas);
  REQUIRE(inside.size() < triangles.size());  // the scene has triangles across the border
  const auto buffer_only = LlvmpipeCanvas::Viewport::buffer_only;
  const auto truth = [&](std::span<const tri::SceneTriangle> t) {
    return rows_flipped(oracle_counts(scene.width, scene.height, mirrored(t, scene.height)).counts,
                        scene.width, scene.height);
  };
  // Inside the viewport nothing is clipped and the mirrored oracle holds, viewport or not...
  CHECK(llvmpipe_counts_in_child(scene.width, scene.height, inside, buffer_only) == truth(inside));
  // ...but clipping the others at the buffer's border changes pixels; the guard band does not.
  CHECK(llvmpipe_counts_in_child(scene.width, scene.height, triangles, buffer_only) !=
        truth(triangles));
  CHECK(llvmpipe_counts_in_child(scene.width, scene.height, triangles) == truth(triangles));
}

TEST_CASE("The llvmpipe peer measures in a child what it measures here", "[peers][llvmpipe]") {
  tri::ch10::BenchSettings settings = tri::ch10::bench_settings(tri::ch10::SuiteSize::tiny);
  const tri::PreparedScene prepared = tri::prepare_scene(settings.scenes.front(), 0);
  const auto here = tri::run_in_child<tri::PeerResult>(
      [&] { return tri::measure_llvmpipe_here(prepared, settings.timing); });
  const auto counts =
      llvmpipe_counts_in_child(prepared.scene.width, prepared.scene.height, prepared.triangles);
  CHECK(here.written_pixels == std::accumulate(counts.begin(), counts.end(), std::uint64_t{0}));
  const auto expected = tri::measure_error(
      [](int w, int h, std::span<const tri::SceneTriangle> t) {
        return tri::WriteCounts{llvmpipe_counts_in_child(w, h, t)};
      },
      prepared.error_scene);
  CHECK(here.error.missed == expected.missed);
  CHECK(here.error.extra == expected.extra);
  CHECK(here.error.covered == expected.covered);
  CHECK(here.timing.seconds.median > 0);
  for (const tri::ExternalPeer& peer : tri::llvmpipe_peers()) {
    CAPTURE(peer.name);
    CHECK(peer.rule == tri::CoverageRule::bottom_left);  // what the mirrored test above shows
    const tri::PeerResult there = peer.measure(prepared, settings.timing);
    CHECK(there.written_pixels == here.written_pixels);
    CHECK(there.error.missed == here.error.missed);
    CHECK(there.error.extra == here.error.extra);
    CHECK(there.error.order_dependent == here.error.order_dependent);
  }
}
