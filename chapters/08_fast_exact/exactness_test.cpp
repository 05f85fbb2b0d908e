// Every variant of the chapter against the oracle (chapter 07), through the registry's entry.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <set>
#include <string_view>
#include <utility>
#include <vector>

#include "chapters/07_exact_coverage/coverage_oracle.hpp"
#include "chapters/07_exact_coverage/fixed_point.hpp"
#include "chapters/08_fast_exact/algorithms.hpp"
#include "chapters/08_fast_exact/hybrid.hpp"
#include "chapters/08_fast_exact/test_triangles.hpp"
#include "tests/support/pixels.hpp"

using tri::Canvas;
using tri::Triangle;
using tri::TriangleAlgorithm;

namespace {

// The canvas a draw function leaves, with write counts, on a background the colour never is.
Canvas drawn_with_counts(tri::DrawTriangleFunction draw, const Triangle& t, int width, int height) {
  Canvas canvas(width, height, tri::Color{9, 9, 9, 255});
  canvas.enable_write_counts();
  draw(canvas, t, tri::colors::white);
  return canvas;
}

// The same without counting: the direct row writes.
Canvas drawn(tri::DrawTriangleFunction draw, const Triangle& t, int width, int height) {
  Canvas canvas(width, height, tri::Color{9, 9, 9, 255});
  draw(canvas, t, tri::colors::white);
  return canvas;
}

bool same_counts(const Canvas& a, const Canvas& b) {
  return std::equal(a.write_counts().begin(), a.write_counts().end(), b.write_counts().begin(),
                    b.write_counts().end());
}

bool same_colors(const Canvas& a, const Canvas& b) {
  return std::equal(a.pixels().begin(), a.pixels().end(), b.pixels().begin(), b.pixels().end());
}

}  // namespace

TEST_CASE("The chapter registers exact variants under distinct names of its own",
          "[08_fast_exact][exactness]") {
  const auto algorithms = tri::ch08::triangle_algorithms();
  REQUIRE(!algorithms.empty());
  std::set<std::string_view> names;
  for (const TriangleAlgorithm& algorithm : algorithms) {
    INFO(algorithm.name);
    CHECK(algorithm.name.starts_with("fast_"));
    CHECK(names.insert(algorithm.name).second);
    CHECK(algorithm.chapter == "08_fast_exact");
    CHECK(algorithm.rule == tri::CoverageRule::top_left);
    CHECK(algorithm.threaded == algorithm.name.ends_with("_threaded"));
  }
  // Two draw step 8's narrow canvases (the span walker alone and after the batched setup), each
  // through its narrow draw, and one is followed by the report's sweeps.
  CHECK(std::count_if(algorithms.begin(), algorithms.end(), [](const TriangleAlgorithm& a) {
          return a.outputs.has(tri::Output::index8) && a.outputs.has(tri::Output::mask1) &&
                 a.draw_narrow != nullptr;
        }) == 2);
  CHECK(tri::algorithm_with_role(algorithms, tri::Role::cost_sweeps) != nullptr);
}

TEST_CASE("Every variant draws exactly the oracle's pixels on 1/256-grid triangles",
          "[08_fast_exact][exactness]") {
  // All shapes (tiny to huge, slivers, pixel-centre ties, far and ±2^30 vertices), all six vertex
  // orders (both windings), on canvases whose sides are not multiples of 8 or 16.
  tri::testing::Random random(2024);
  for (int i = 0; i < 1400; ++i) {
    const int width = i % 2 == 0 ? 45 : 21, height = i % 3 == 0 ? 37 : 19;
    const Triangle t =
        tri::ch08::testing::random_triangle(random, tri::ch08::testing::shape_number(i), 40);
    const Canvas truth = drawn_with_counts(tri::ch07::draw_triangle_oracle, t, width, height);
    const Canvas truth_colors = drawn(tri::ch07::draw_triangle_oracle, t, width, height);
    for (const TriangleAlgorithm& algorithm : tri::ch08::triangle_algorithms()) {
      for (const Triangle& u : tri::testing::vertex_orders(t)) {
        INFO(algorithm.name << ", triangle " << i << ": " << u[0].x << "," << u[0].y << " "
                            << u[1].x << "," << u[1].y << " " << u[2].x << "," << u[2].y);
        const Canvas counted = drawn_with_counts(algorithm.draw, u, width, height);
        REQUIRE(counted.outside_writes() == 0);
        REQUIRE(same_counts(counted, truth));
        const Canvas plain = drawn(algorithm.draw, u, width, height);
        REQUIRE(plain.outside_writes() == 0);
        REQUIRE(same_colors(plain, truth_colors));
      }
    }
  }
}

TEST_CASE("On arbitrary doubles every variant snaps exactly as chapter 07's fixed_point_8",
          "[08_fast_exact][exactness]") {
  tri::testing::Random random(77);
  for (int i = 0; i < 1500; ++i) {
    const Triangle t = tri::testing::random_real_triangle(random, -6, 38);
    const Canvas reference = drawn_with_counts(tri::ch07::draw_triangle_fixed_point_8, t, 33, 33);
    for (const TriangleAlgorithm& algorithm : tri::ch08::triangle_algorithms()) {
      INFO(algorithm.name << ", triangle " << i);
      REQUIRE(same_counts(drawn_with_counts(algorithm.draw, t, 33, 33), reference));
    }
  }
}

TEST_CASE("Every variant is safe on degenerate, tiny-canvas and refused input",
          "[08_fast_exact][exactness]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double far = 1073741824.0;
  const std::vector<Triangle> cases{
      {{{0, 0}, {0, 0}, {0, 0}}},
      {{{1, 1}, {9, 9}, {5, 5}}},
      {{{0, 3}, {7, 3}, {3, 3}}},
      {{{1e7, 1e7}, {-1e7, 1e7}, {0, -1e7}}},
      {{{-far, -far}, {far, -far}, {0, far}}},
      {{{-far, far}, {far, far}, {far, -far}}},
      {{{0.5, 0.5}, {0.5, 0.5}, {0.75, 0.5}}},
      {{{-3, -3}, {-1, -3}, {-2, -1}}},
  };
  for (const TriangleAlgorithm& algorithm : tri::ch08::triangle_algorithms()) {
    for (const int size : {1, 3, 8, 9}) {
      for (const Triangle& t : cases) {
        INFO(algorithm.name << " on a " << size << "x" << size << " canvas");
        const Canvas truth = drawn_with_counts(tri::ch07::draw_triangle_oracle, t, size, size + 2);
        const Canvas counted = drawn_with_counts(algorithm.draw, t, size, size + 2);
        CHECK(counted.outside_writes() == 0);
        CHECK(same_counts(counted, truth));
      }
    }
    Canvas canvas(8, 8);
    canvas.enable_write_counts();
    CHECK(tri::draw_triangle(algorithm, canvas, {{{0, 0}, {7, 0}, {nan, 7}}}, tri::colors::white) ==
          tri::DrawResult::rejected_non_finite);
    CHECK(tri::testing::written_pixels(canvas).empty());
  }
}

TEST_CASE("Batches through the registry's entry point equal drawing one by one",
          "[08_fast_exact][step6]") {
  // fast_hybrid, fast_threaded and fast_batched have batch entries, fast_tiled_threaded a renderer;
  // draw_triangles uses them.
  tri::testing::Random random(31);
  std::vector<tri::SceneTriangle> scene;
  for (int i = 0; i < 300; ++i) {
    scene.push_back(
        {tri::ch08::testing::random_triangle(random, tri::ch08::testing::shape_number(i), 50),
         tri::Color{static_cast<std::uint8_t>(i), 100, 200, 255}});
  }
  for (const TriangleAlgorithm& algorithm : tri::ch08::triangle_algorithms()) {
    INFO(algorithm.name);
    Canvas batch(50, 47), one_by_one(50, 47);
    batch.enable_write_counts();
    one_by_one.enable_write_counts();
    CHECK(tri::draw_triangles(algorithm, batch, scene) == 0);
    for (const auto& t : scene) tri::ch07::draw_triangle_oracle(one_by_one, t.vertices, t.color);
    CHECK(same_colors(batch, one_by_one));
    CHECK(same_counts(batch, one_by_one));
    CHECK(batch.outside_writes() == 0);
  }
}

TEST_CASE("One drawer kept for successive batches draws what fast_hybrid draws serially",
          "[08_fast_exact][step9]") {
  // Each variant's drawer (fast_tiled_threaded's keeps its threads and bins) draws batches of
  // overlapping colours on canvases of several sizes in turn, one batch with refused triangles
  // among the others; every batch must equal the serial fast_hybrid of its accepted triangles.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::array<std::pair<int, int>, 6> sizes{
      {{150, 140}, {1100, 70}, {1, 1}, {600, 130}, {65, 13}, {150, 140}}};
  for (const TriangleAlgorithm& algorithm : tri::ch08::triangle_algorithms()) {
    tri::BatchDrawer drawer(algorithm);
    for (std::size_t b = 0; b < sizes.size(); ++b) {
      const auto [width, height] = sizes[b];
      auto batch = tri::ch08::testing::overlapping_scene(40 + b, 500, std::max(width, height));
      std::size_t refused = 0;
      if (b == 2 || b == 3) {
        // Refused triangles at the start, in the middle and at the end of the batch.
        for (const std::size_t at : {std::size_t{0}, batch.size() / 2, batch.size()}) {
          const Triangle bad =
              b == 2 ? Triangle{{{0, 0}, {nan, 5}, {5, 0}}} : Triangle{{{0, 0}, {2e9, 5}, {5, 0}}};
          batch.insert(batch.begin() + static_cast<std::ptrdiff_t>(at),
                       {bad, tri::Color{255, 0, 0, 255}});
          ++refused;
        }
      }
      for (const bool counting : {true, false}) {
        INFO(algorithm.name << ", batch " << b << " on " << width << "x" << height << ", counting "
                            << counting);
        const Canvas serial = tri::ch08::testing::drawn_on(width, height, counting, [&](Canvas& c) {
          for (const auto& t : batch) {
            if (tri::validate_triangle(t.vertices) == tri::DrawResult::drawn)
              tri::ch08::draw_triangle_hybrid(c, t.vertices, t.color);
          }
        });
        std::size_t reported = 0;
        const Canvas kept = tri::ch08::testing::drawn_on(
            width, height, counting, [&](Canvas& c) { reported = drawer.draw(c, batch); });
        CHECK(reported == refused);
        CHECK(kept.outside_writes() == 0);
        CHECK(tri::ch08::testing::same_canvas(kept, serial));
      }
    }
  }
}

TEST_CASE("A variant has at most one batch entry, and the tiled one keeps a renderer",
          "[08_fast_exact][step9]") {
  for (const TriangleAlgorithm& algorithm : tri::ch08::triangle_algorithms()) {
    INFO(algorithm.name);
    CHECK(!(algorithm.draw_batch != nullptr && algorithm.make_renderer != nullptr));
    CHECK((algorithm.make_renderer != nullptr) == (algorithm.name == "fast_tiled_threaded"));
  }
}
