#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <variant>
#include <vector>

#include <catch2/catch.hpp>

#include "measure/registry.hpp"
#include "measure/render_scene.hpp"

namespace tri {
namespace {

constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();

// Triangles of every kind a scene holds (ordinary, clockwise, partly off the canvas, refused as
// NaN or out of range) with lines between runs of them, so the order of runs and lines matters.
Scene mixed_scene() {
  Scene scene;
  scene.width = 24;
  scene.height = 20;
  const auto triangle = [&](glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, std::uint8_t red) {
    scene.primitives.emplace_back(SceneTriangle{{a, b, c}, Color{red, 40, 80, 255}});
  };
  const auto line = [&](glm::dvec2 a, glm::dvec2 b, std::uint8_t red) {
    scene.primitives.emplace_back(SceneLine{{a, b}, Color{red, 200, 0, 255}});
  };
  triangle({1, 1}, {20, 2}, {3, 17}, 10);
  triangle({2.5, 3.25}, {22.75, 18.5}, {18, 1.5}, 20);  // clockwise
  line({0, 0}, {23, 19}, 30);
  triangle({not_a_number, 1}, {5, 5}, {1, 9}, 40);
  triangle({-7, -3}, {30, 4}, {6, 26}, 50);  // partly off the canvas
  triangle({1, 1}, {2e9, 1}, {1, 5}, 60);    // beyond ±2^30
  line({23, 0}, {0, 19}, 70);
  line({4, 10}, {20, 10}, 80);
  triangle({5, 5}, {12, 5}, {5, 12}, 90);
  return scene;
}

bool same_pixels(const Canvas& a, const Canvas& b) {
  return std::equal(a.pixels().begin(), a.pixels().end(), b.pixels().begin(), b.pixels().end(),
                    [](Color p, Color q) { return p == q; }) &&
         std::equal(a.write_counts().begin(), a.write_counts().end(), b.write_counts().begin(),
                    b.write_counts().end());
}

}  // namespace

TEST_CASE("A prepared scene keeps its runs of triangles and its lines in order, checked once",
          "[measure][render]") {
  const PreparedDrawing prepared = prepare_drawing(mixed_scene());
  REQUIRE(prepared.steps.size() == 6);
  const auto batch = [&](std::size_t i) { return std::get<PreparedBatch>(prepared.steps[i]); };
  CHECK(batch(0).triangles().size() == 2);
  CHECK(batch(0).refused() == 0);
  CHECK(std::get<SceneLine>(prepared.steps[1]).color.r == 30);
  CHECK(batch(2).triangles().size() == 1);
  CHECK(batch(2).triangles()[0].color.r == 50);
  CHECK(batch(2).refused() == 2);
  CHECK(std::get<SceneLine>(prepared.steps[3]).color.r == 70);
  CHECK(std::get<SceneLine>(prepared.steps[4]).color.r == 80);
  CHECK(batch(5).triangles()[0].color.r == 90);
  CHECK(prepared.stats.triangles == 4);
  CHECK(prepared.stats.lines == 3);
  CHECK(prepared.stats.rejected_triangles == 2);
}

TEST_CASE("Every algorithm draws a prepared scene as render_scene draws the scene",
          "[measure][render]") {
  const Scene scene = mixed_scene();
  const PreparedDrawing prepared = prepare_drawing(scene);
  for (const TriangleAlgorithm& algorithm : registered_algorithms()) {
    CAPTURE(algorithm.name);
    Canvas rendered = make_canvas(scene);
    rendered.enable_write_counts();
    BatchDrawer drawer(algorithm);
    const RenderStats expected = render_scene(scene, &algorithm, rendered);
    // Drawn twice with one drawer, as a benchmark's frames are: the same every time.
    for (int frame = 0; frame < 2; ++frame) {
      Canvas canvas = make_canvas(scene);
      canvas.enable_write_counts();
      const RenderStats stats = draw_prepared(prepared, &drawer, canvas);
      CHECK(stats.triangles == expected.triangles);
      CHECK(stats.lines == expected.lines);
      CHECK(stats.rejected_triangles == expected.rejected_triangles);
      CHECK(same_pixels(canvas, rendered));
      CHECK(canvas.outside_writes() == rendered.outside_writes());
    }
  }
}

TEST_CASE(
    "Every algorithm draws a scene prepared with its triangles culled as render_scene draws it, "
    "with triangles partly and wholly off the canvas",
    "[measure][render]") {
  // Small triangles whose boxes end at distances around half and one pixel beyond each edge of
  // a 12 x 10 canvas, where rounding to pixel centres decides, with large ones partly off it,
  // refused ones off it, and lines between the runs.
  Scene scene;
  scene.width = 12;
  scene.height = 10;
  std::uint8_t red = 0;
  const auto triangle = [&](glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
    red = static_cast<std::uint8_t>(red + 7);
    scene.primitives.emplace_back(SceneTriangle{{a, b, c}, Color{red, 90, 30, 255}});
  };
  const double beyond[] = {-0.3, 0.0, 0.25, 0.49, 0.5, 0.51, 0.75, 0.99, 1.0, 1.01, 1.5, 3.0};
  for (const double d : beyond) {
    // Right-angled, 2 pixels wide and tall, its box ending d beyond the edge's last centre.
    triangle({-d, 3}, {-d - 2, 3}, {-d, 5.5});                     // left of column 0
    triangle({11 + d, 4}, {13 + d, 4}, {11 + d, 6.25});            // right of column 11
    triangle({5, -d}, {7.5, -d}, {5, -d - 2});                     // below row 0
    triangle({6, 9 + d}, {6, 11 + d}, {3.75, 9 + d});              // above row 9
    triangle({-d, -d}, {-d - 2, -d}, {-d, -d - 2});                // beyond a corner
    triangle({-d - 0.5, 2.5}, {-d - 1.5, 2.5}, {-d - 0.75, 3.5});  // a sliver, clockwise
  }
  scene.primitives.emplace_back(SceneLine{{glm::dvec2(0, 0), glm::dvec2(11, 9)}});
  triangle({-30, -20}, {40, 5}, {2, 30});              // partly off, large
  triangle({500, 500}, {600, 520}, {510, 700});        // wholly off
  triangle({-500, 5}, {not_a_number, 6}, {-510, 7});   // refused, off the canvas
  triangle({-500, 5}, {-2e9, 6}, {-510, 7});           // refused, off the canvas
  triangle({-1000, -1000}, {1000, -1000}, {0, 1000});  // covers the canvas
  triangle({2.5, 2.5}, {9.5, 3.5}, {4.5, 8.5});        // inside
  const PreparedDrawing prepared = prepare_drawing(scene);
  std::size_t culled = 0, kept = 0;
  for (const auto& step : prepared.steps) {
    if (const auto* batch = std::get_if<PreparedBatch>(&step)) {
      culled += batch->culled();
      kept += batch->triangles().size();
    }
  }
  CHECK(culled > 0);
  CHECK(kept > 4);
  CHECK(culled + kept + prepared.stats.rejected_triangles == count_triangles(scene));
  for (const TriangleAlgorithm& algorithm : registered_algorithms()) {
    CAPTURE(algorithm.name);
    Canvas rendered = make_canvas(scene);
    rendered.enable_write_counts();
    const RenderStats expected = render_scene(scene, &algorithm, rendered);
    BatchDrawer drawer(algorithm);
    Canvas canvas = make_canvas(scene);
    canvas.enable_write_counts();
    const RenderStats stats = draw_prepared(prepared, &drawer, canvas);
    CHECK(stats.triangles == expected.triangles);
    CHECK(stats.rejected_triangles == expected.rejected_triangles);
    CHECK(same_pixels(canvas, rendered));
  }
}

TEST_CASE("A prepared scene with triangles needs a drawer", "[measure][render]") {
  const PreparedDrawing prepared = prepare_drawing(mixed_scene());
  Canvas canvas = make_canvas(mixed_scene());
  CHECK_THROWS_AS(draw_prepared(prepared, nullptr, canvas), std::logic_error);
  Scene lines_only;
  lines_only.width = lines_only.height = 8;
  lines_only.primitives.emplace_back(SceneLine{{glm::dvec2(0, 0), glm::dvec2(7, 7)}});
  Canvas small = make_canvas(lines_only);
  CHECK(draw_prepared(prepare_drawing(lines_only), nullptr, small).lines == 1);
  CHECK(small.pixel(3, 3) == colors::white);
}

}  // namespace tri
