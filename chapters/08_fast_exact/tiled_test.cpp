#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <vector>

#include "chapters/07_exact_coverage/coverage_oracle.hpp"
#include "chapters/08_fast_exact/hybrid.hpp"
#include "chapters/08_fast_exact/test_triangles.hpp"
#include "chapters/08_fast_exact/tiled.hpp"

using tri::Canvas;
using tri::SceneTriangle;
using tri::ch08::TileBins;
using tri::ch08::testing::drawn_on;
using tri::ch08::testing::overlapping_scene;
using tri::ch08::testing::same_canvas;

namespace {

// The scene drawn one triangle after the other by chapter 07's oracle.
Canvas oracle_canvas(int width, int height, const std::vector<SceneTriangle>& scene,
                     bool counting) {
  return drawn_on(width, height, counting, [&](Canvas& canvas) {
    for (const auto& t : scene) tri::ch07::draw_triangle_oracle(canvas, t.vertices, t.color);
  });
}

// Triangles around the tile corner (512, 64) of a 600 x 128 canvas (tiles of 512 x 16): edges
// along the last column and row of one tile and the first of the next, vertices on them, and
// triangles that cross the seams.
std::vector<SceneTriangle> seam_scene() {
  std::vector<SceneTriangle> scene;
  const glm::dvec2 corner{512, 64};
  const auto add = [&](glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
    const auto level = static_cast<std::uint8_t>(40 + 5 * scene.size());
    scene.push_back({{corner + a, corner + b, corner + c},
                     tri::Color{level, static_cast<std::uint8_t>(255 - level), 90, 255}});
  };
  for (const double seam : {-1.0, -0.5, 0.0}) {
    add({seam, -14}, {seam, 14}, {-14, 0});  // an edge down a seam column, left of it
    add({seam, -14}, {14, 0}, {seam, 14});   // the same edge, right of it
    add({-14, seam}, {14, seam}, {0, -14});  // an edge along a seam row, below it
    add({-14, seam}, {0, 14}, {14, seam});   // above it
    add({seam, seam}, {seam + 9, seam}, {seam, seam + 9});  // a vertex on the corner
  }
  // A fan around the corner, sharing its edges: every centre on them goes to one triangle.
  const glm::dvec2 around[] = {{-24, 0}, {-24, -24}, {0, -24}, {24, -24},
                               {24, 0},  {24, 24},   {0, 24},  {-24, 24}};
  for (int i = 0; i < 8; ++i) add({0, 0}, around[i], around[(i + 1) % 8]);
  // Long slivers across both seams, and a triangle over every tile.
  add({-60, -60}, {60, 60}, {-59.5, -60});
  add({60, -60}, {-60, 59.75}, {60, -59.75});
  add({-600, -100}, {200, -100}, {-200, 200});
  return scene;
}

// The scene drawn tile after tile by one TileBins on this thread: binned (bands 0) or in at most
// `bands` unbinned bands of rows.
Canvas drawn_by_tiles(int width, int height, const std::vector<SceneTriangle>& scene, int bands,
                      bool counting) {
  TileBins bins;
  bins.start(scene, width, height, bands);
  for (int chunk = 0; chunk < bins.chunks(); ++chunk) bins.bin_chunk(chunk);
  return drawn_on(width, height, counting, [&](Canvas& canvas) {
    for (int tile = 0; tile < bins.grid().count(); ++tile) bins.draw_tile(canvas, tile);
  });
}

}  // namespace

TEST_CASE("Tiles are 512 pixels wide and 64 rows tall, fewer rows on a small canvas",
          "[08_fast_exact][step9]") {
  const auto grid = tri::ch08::tile_grid_for(4096, 4096);
  CHECK((grid.tile_width() == 512 && grid.tile_height() == 64));
  CHECK((grid.columns == 8 && grid.rows == 64));
  const auto box = grid.tile(9, 4096, 4096);
  CHECK((box.min.x == 512 && box.min.y == 64 && box.max.x == 1023 && box.max.y == 127));
  // 512 x 512: eight tiles of 64 rows would be too few to share out, 16 of 32 rows are not.
  const auto square = tri::ch08::tile_grid_for(512, 512);
  CHECK((square.tile_height() == 32 && square.count() == 16));
  // Cut by the border: the last column and row are narrower.
  const auto cut = tri::ch08::tile_grid_for(1000, 300);
  CHECK((cut.columns == 2 && cut.tile_height() == 32 && cut.rows == 10));
  const auto last = cut.tile(cut.count() - 1, 1000, 300);
  CHECK((last.min.x == 512 && last.min.y == 288 && last.max.x == 999 && last.max.y == 299));
  const auto one = tri::ch08::tile_grid_for(1, 1);
  CHECK(one.count() == 1);
  CHECK((one.tile(0, 1, 1).max.x == 0 && one.tile(0, 1, 1).max.y == 0));
}

TEST_CASE("The box binning reads from doubles holds every candidate pixel of the snapped triangle",
          "[08_fast_exact][step9]") {
  tri::testing::Random random(90);
  for (int i = 0; i < 20000; ++i) {
    const int width = 1 + i % 70, height = 1 + i % 53;
    const auto t = tri::ch08::testing::random_triangle(random, tri::ch08::testing::shape_number(i),
                                                       std::max(width, height));
    const auto around = tri::ch08::pixels_around(t, width, height);
    const auto setup = tri::ch08::setup_triangle(t, width, height);
    if (!setup) continue;
    INFO("triangle " << i << " on " << width << "x" << height);
    REQUIRE(!around.empty());
    CHECK(around.min.x <= setup->range.min.x);
    CHECK(around.min.y <= setup->range.min.y);
    CHECK(around.max.x >= setup->range.max.x);
    CHECK(around.max.y >= setup->range.max.y);
    CHECK((around.min.x >= 0 && around.min.y >= 0));
    CHECK((around.max.x < width && around.max.y < height));
  }
}

TEST_CASE("Every tile lists, in submission order, each triangle that covers one of its pixels",
          "[08_fast_exact][step9]") {
  for (const auto& [width, height] :
       {std::pair{150, 140}, std::pair{600, 100}, std::pair{64, 64}, std::pair{7, 200}}) {
    const auto scene = overlapping_scene(static_cast<std::uint64_t>(width + height), 300, 150);
    TileBins bins;
    bins.start(scene, width, height);
    for (int chunk = bins.chunks() - 1; chunk >= 0; --chunk) bins.bin_chunk(chunk);
    const auto grid = bins.grid();
    std::vector<std::vector<std::uint32_t>> listed;
    for (int tile = 0; tile < grid.count(); ++tile) {
      listed.push_back(bins.triangles_of(tile));
      INFO(width << "x" << height << ", tile " << tile);
      CHECK(std::is_sorted(listed.back().begin(), listed.back().end()));
      CHECK(std::adjacent_find(listed.back().begin(), listed.back().end()) == listed.back().end());
    }
    for (std::uint32_t i = 0; i < scene.size(); ++i) {
      Canvas alone(width, height);
      alone.enable_write_counts();
      tri::ch07::draw_triangle_oracle(alone, scene[i].vertices, scene[i].color);
      for (const auto& [x, y] : tri::testing::written_pixels(alone)) {
        const int tile = (y >> grid.height_bits) * grid.columns + (x >> grid.width_bits);
        const auto& list = listed[static_cast<std::size_t>(tile)];
        INFO(width << "x" << height << ", triangle " << i << " covers " << x << "," << y);
        REQUIRE(std::binary_search(list.begin(), list.end(), i));
      }
    }
  }
}

TEST_CASE("The tiled batch equals the oracle and the serial batch, colours and write counts",
          "[08_fast_exact][step9]") {
  // Overlapping colours across tile borders, every shape of triangle, canvases of one pixel to
  // three tiles wide whose sides are not multiples of the tile's; one to seven threads, each
  // renderer (its threads and bins) reused for every frame.
  std::vector<std::unique_ptr<tri::ch08::TiledRenderer>> renderers;
  for (const int threads : {1, 2, 3, 7})
    renderers.push_back(std::make_unique<tri::ch08::TiledRenderer>(threads));
  for (const auto& [width, height] :
       {std::pair{150, 140}, std::pair{1100, 70}, std::pair{530, 40}, std::pair{129, 64},
        std::pair{1, 1}, std::pair{3, 5}, std::pair{8, 8}, std::pair{65, 13}, std::pair{13, 200}}) {
    const int size = std::max(width, height);
    const auto scene = overlapping_scene(static_cast<std::uint64_t>(width * height), 600, size);
    for (const bool counting : {true, false}) {
      const Canvas truth = oracle_canvas(width, height, scene, counting);
      REQUIRE(same_canvas(
          drawn_on(width, height, counting,
                   [&](Canvas& canvas) { tri::ch08::draw_batch_hybrid(canvas, scene); }),
          truth));
      for (std::size_t r = 0; r < renderers.size(); ++r) {
        INFO(width << "x" << height << ", renderer " << r << ", counting " << counting);
        const Canvas tiled = drawn_on(width, height, counting,
                                      [&](Canvas& canvas) { renderers[r]->draw(canvas, scene); });
        CHECK(tiled.outside_writes() == 0);
        CHECK(same_canvas(tiled, truth));
      }
      // The registered renderer, made for this one batch.
      CHECK(same_canvas(
          drawn_on(width, height, counting,
                   [&](Canvas& canvas) { tri::ch08::make_tiled_renderer()->draw(canvas, scene); }),
          truth));
    }
  }
}

TEST_CASE("Triangles with edges and vertices on tile seams are drawn as the oracle draws them",
          "[08_fast_exact][step9]") {
  const auto scene = seam_scene();
  for (const bool counting : {true, false}) {
    const Canvas truth = oracle_canvas(600, 128, scene, counting);
    // Binned (the renderer bins only canvases larger than this one) and in bands of rows.
    for (const int bands : {0, 1, 2, 3}) {
      INFO(bands << " bands, counting " << counting);
      CHECK(same_canvas(drawn_by_tiles(600, 128, scene, bands, counting), truth));
    }
    for (const int threads : {1, 2, 4}) {
      INFO(threads << " threads, counting " << counting);
      tri::ch08::TiledRenderer renderer(threads);
      CHECK(same_canvas(
          drawn_on(600, 128, counting, [&](Canvas& canvas) { renderer.draw(canvas, scene); }),
          truth));
    }
  }
}

TEST_CASE("A renderer's threads wait between batches and stop when it goes",
          "[08_fast_exact][step9]") {
  // Batches of every size in turn, empty ones included, through renderers made and dropped.
  const auto scene = overlapping_scene(23, 300, 100);
  const Canvas truth = oracle_canvas(100, 90, scene, true);
  for (int round = 0; round < 20; ++round) {
    tri::ch08::TiledRenderer renderer(1 + round % 4);
    for (const std::size_t count : {std::size_t{0}, std::size_t{1}, scene.size()}) {
      const std::vector<SceneTriangle> part(scene.begin(),
                                            scene.begin() + static_cast<std::ptrdiff_t>(count));
      const Canvas drawn =
          drawn_on(100, 90, true, [&](Canvas& canvas) { renderer.draw(canvas, part); });
      if (count == scene.size()) CHECK(same_canvas(drawn, truth));
      if (count == 0) CHECK(tri::testing::written_pixels(drawn).empty());
    }
  }
}

TEST_CASE("Each tile draws only its own pixels, and the tiles together draw the whole batch",
          "[08_fast_exact][step9]") {
  const auto scene = overlapping_scene(17, 400, 700);
  const Canvas serial = drawn_on(
      700, 130, true, [&](Canvas& canvas) { tri::ch08::draw_batch_hybrid(canvas, scene); });
  // Binned tiles (bands 0), and unbinned bands of rows as the renderer draws a small canvas.
  for (const int bands : {0, 1, 2, 3, 7}) {
    TileBins bins;
    bins.start(scene, 700, 130, bands);
    for (int chunk = 0; chunk < bins.chunks(); ++chunk) bins.bin_chunk(chunk);
    if (bands > 0) CHECK(bins.grid().count() <= bands);
    for (int tile = 0; tile < bins.grid().count(); ++tile) {
      const Canvas alone =
          drawn_on(700, 130, true, [&](Canvas& canvas) { bins.draw_tile(canvas, tile); });
      const auto box = bins.grid().tile(tile, 700, 130);
      for (const auto& [x, y] : tri::testing::written_pixels(alone)) {
        INFO(bands << " bands: tile " << tile << " wrote " << x << "," << y);
        REQUIRE((x >= box.min.x && x <= box.max.x && y >= box.min.y && y <= box.max.y));
      }
    }
    INFO(bands << " bands");
    CHECK(same_canvas(drawn_by_tiles(700, 130, scene, bands, true), serial));
  }
}
