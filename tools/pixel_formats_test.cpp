// The narrow formats against the RGBA8 canvas on seeded random scenes: whatever the triangles
// (on and off the grid, far away, refused), index8 and mask1 expand to the pixels fast_spans
// draws in RGBA8.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>

#include "common/random.hpp"
#include "common/scene.hpp"
#include "measure/registry.hpp"
#include "measure/render_scene.hpp"
#include "tools/pixel_formats.hpp"

namespace {

// A coordinate of one of five kinds: on the 1/256 grid near the canvas, any double near it, far
// (up to ±2^30), exactly ±2^30, or (rarely) NaN, which the formats must refuse as RGBA8 does.
double random_coordinate(tri::Random& random, int side) {
  switch (random.integer(0, 9)) {
    case 0:
      return random.real(-tri::max_scene_coordinate, tri::max_scene_coordinate);
    case 1:
      return random.integer(0, 1) == 0 ? tri::max_scene_coordinate : -tri::max_scene_coordinate;
    case 2:
      return random.integer(0, 20) == 0 ? std::numeric_limits<double>::quiet_NaN()
                                        : random.real(-8, side + 8);
    case 3:
    case 4:
      return random.real(-8, side + 8);
    default:
      return random.integer(-8 * 256, (side + 8) * 256) / 256.0;
  }
}

tri::Scene random_scene(tri::Random& random, int colors) {
  tri::Scene scene;
  scene.width = random.integer(1, 70);
  scene.height = random.integer(1, 70);
  scene.background = {10, 20, 30, 255};
  const int count = random.integer(1, 40);
  for (int i = 0; i < count; ++i) {
    tri::SceneTriangle t;
    for (auto& v : t.vertices) {
      v = {random_coordinate(random, scene.width), random_coordinate(random, scene.height)};
    }
    const int c = random.integer(0, colors - 1);
    t.color = {static_cast<std::uint8_t>(c), static_cast<std::uint8_t>(255 - c), 99, 255};
    scene.primitives.emplace_back(t);
  }
  return scene;
}

}  // namespace

TEST_CASE("index8 and mask1 expand to the RGBA8 pixels on seeded random scenes",
          "[raster][format]") {
  const auto drawables = tri::registered_drawables();
  const auto narrow_drawers = tri::drawables_writing(drawables, tri::Output::index8);
  // NarrowRender draws with each one's draw_narrow entry: chapter 08's span walker, alone and
  // after the batched setup.
  REQUIRE(narrow_drawers.size() == 2);
  for (const tri::Drawable* drawer : narrow_drawers) {
    REQUIRE(drawer->writes(tri::Output::mask1));
    const tri::TriangleAlgorithm* algorithm = drawer->colours;
    REQUIRE(algorithm != nullptr);
    REQUIRE(algorithm->draw_narrow != nullptr);
    CAPTURE(algorithm->name);
    tri::Random random(23);
    std::size_t refusals = 0;
    int mask1_scenes = 0;
    for (int trial = 0; trial < 120; ++trial) {
      const int colors = trial % 3 == 0 ? 1 : random.integer(2, 255);
      const tri::Scene scene = random_scene(random, colors);
      tri::Canvas rgba(scene.width, scene.height, scene.background);
      const std::size_t refused = tri::render_scene(scene, algorithm, rgba).rejected_triangles;
      refusals += refused;
      mask1_scenes += !tri::format_refusal(scene, tri::PixelFormat::mask1);
      for (const tri::PixelFormat format : {tri::PixelFormat::index8, tri::PixelFormat::mask1}) {
        if (tri::format_refusal(scene, format)) continue;  // mask1 holds one colour only
        CAPTURE(trial, tri::format_name(format), scene.width, scene.height);
        tri::NarrowRender narrow(scene, format, *algorithm);
        CHECK(narrow.draw() == refused);
        const tri::Canvas expanded = narrow.expanded();
        int differing = 0;
        for (int y = 0; y < scene.height; ++y) {
          for (int x = 0; x < scene.width; ++x) {
            differing += expanded.pixel(x, y) != rgba.pixel(x, y);
          }
        }
        CHECK(differing == 0);
      }
    }
    CHECK(refusals > 0);  // the NaN vertices were drawn too
    CHECK(mask1_scenes >= 30);
  }
}

TEST_CASE("Every registered drawable that declares the narrow formats has a narrow draw",
          "[raster][format]") {
  for (const tri::Drawable& d : tri::registered_drawables()) {
    CAPTURE(d.name);
    const bool narrow = d.writes(tri::Output::index8) || d.writes(tri::Output::mask1);
    CHECK(narrow == (d.colours != nullptr && d.colours->draw_narrow != nullptr));
  }
}
