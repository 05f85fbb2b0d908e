#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "chapters/08_fast_exact/batched.hpp"
#include "chapters/08_fast_exact/hybrid.hpp"
#include "chapters/08_fast_exact/narrow_canvases.hpp"
#include "chapters/08_fast_exact/test_triangles.hpp"
#include "chapters/08_fast_exact/triangle_setup.hpp"

using tri::Canvas;
using tri::SceneTriangle;
using tri::Triangle;
using tri::ch08::LaneResult;
using tri::ch08::SetupLanes;
using tri::ch08::TriangleSetup;

namespace {

bool same_setup(const TriangleSetup& a, const TriangleSetup& b) {
  for (std::size_t e = 0; e < 3; ++e) {
    if (a.edges[e].value != b.edges[e].value || a.edges[e].step_x != b.edges[e].step_x ||
        a.edges[e].step_y != b.edges[e].step_y) {
      return false;
    }
  }
  return a.range.min == b.range.min && a.range.max == b.range.max &&
         a.vertex_extent == b.vertex_extent && a.middle_y == b.middle_y;
}

bool beyond_lanes(const Triangle& t) {
  return std::any_of(t.begin(), t.end(), [](glm::dvec2 v) {
    return std::abs(v.x) > tri::ch08::max_lane_coordinate ||
           std::abs(v.y) > tri::ch08::max_lane_coordinate;
  });
}

// How many lanes took each path.
struct LaneCounts {
  int set_up = 0, nothing = 0, scalar = 0;
};

// Sets up `triangles` in groups of up to `group` lanes and checks every lane against
// setup_triangle: a lane set up in lanes has its fields, a lane with nothing to draw has none,
// and exactly the triangles with a vertex beyond the lanes' bound go to the scalar setup.
void check_lanes(const std::vector<SceneTriangle>& triangles, int width, int height, int group,
                 tri::ch08::InstructionSet set, LaneCounts& counts) {
  SetupLanes lanes;
  for (std::size_t first = 0; first < triangles.size(); first += static_cast<std::size_t>(group)) {
    const std::size_t count = std::min(triangles.size() - first, static_cast<std::size_t>(group));
    tri::ch08::set_up_lanes(std::span(triangles).subspan(first, count), width, height, lanes, set);
    for (std::size_t i = 0; i < tri::ch08::setup_lanes; ++i) {
      if (i >= count) {
        REQUIRE(lanes.result[i] == LaneResult::nothing);
        continue;
      }
      const Triangle& t = triangles[first + i].vertices;
      INFO("triangle " << first + i << ": " << t[0].x << "," << t[0].y << " " << t[1].x << ","
                       << t[1].y << " " << t[2].x << "," << t[2].y << " on " << width << "x"
                       << height << ", copy " << static_cast<int>(set));
      const auto expected = tri::ch08::setup_triangle(t, width, height);
      REQUIRE((lanes.result[i] == LaneResult::scalar) == beyond_lanes(t));
      if (lanes.result[i] == LaneResult::scalar) {
        ++counts.scalar;
      } else if (lanes.result[i] == LaneResult::nothing) {
        ++counts.nothing;
        REQUIRE_FALSE(expected.has_value());
      } else {
        ++counts.set_up;
        REQUIRE(expected.has_value());
        REQUIRE(same_setup(lanes.setup(static_cast<int>(i)), *expected));
      }
    }
  }
}

// check_lanes with the portable copy and with the widest this host runs (AVX2 where it has
// them, else the portable one again).
void check_lanes(const std::vector<SceneTriangle>& triangles, int width, int height, int group,
                 LaneCounts& counts) {
  for (const auto set :
       {tri::ch08::InstructionSet::portable, tri::ch08::widest_instruction_set()}) {
    check_lanes(triangles, width, height, group, set, counts);
  }
}

std::vector<SceneTriangle> in_every_vertex_order(const std::vector<Triangle>& triangles) {
  std::vector<SceneTriangle> all;
  for (const Triangle& t : triangles) {
    for (const Triangle& u : tri::testing::vertex_orders(t)) all.push_back({u});
  }
  return all;
}

// A jittered grid of cells, two triangles each, vertices on the 1/256 grid: shared edges and
// vertices everywhere.
std::vector<Triangle> jittered_mesh(tri::testing::Random& random, int cells, double cell) {
  std::vector<glm::dvec2> points;
  for (int j = 0; j <= cells; ++j) {
    for (int i = 0; i <= cells; ++i) {
      points.push_back({std::floor((i * cell + random.real(-0.3, 0.3) * cell) * 256) / 256,
                        std::floor((j * cell + random.real(-0.3, 0.3) * cell) * 256) / 256});
    }
  }
  const auto at = [&](int i, int j) {
    return points[static_cast<std::size_t>(j * (cells + 1) + i)];
  };
  std::vector<Triangle> mesh;
  for (int j = 0; j < cells; ++j) {
    for (int i = 0; i < cells; ++i) {
      mesh.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      mesh.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return mesh;
}

// The canvas a batch entry leaves, colours and write counts, on a background no triangle has.
Canvas drawn_batch(tri::DrawBatchFunction draw, const std::vector<SceneTriangle>& scene, int width,
                   int height, bool counting) {
  Canvas canvas(width, height, tri::Color{9, 9, 9, 255});
  if (counting) canvas.enable_write_counts();
  draw(canvas, scene);
  return canvas;
}

}  // namespace

TEST_CASE("The lanes set up every triangle exactly as setup_triangle does, field by field",
          "[08_fast_exact][step10]") {
  // Every shape of the chapter's cycle (tiny to ±2^30, slivers, pixel-centre ties, partly off the
  // canvas) in all six vertex orders, so clockwise too, in groups of 1 to 8 lanes.
  tri::testing::Random random(1010);
  std::vector<Triangle> shapes;
  for (int i = 0; i < 3000; ++i) {
    shapes.push_back(
        tri::ch08::testing::random_triangle(random, tri::ch08::testing::shape_number(i), 40));
  }
  // Arbitrary doubles, not on the grid: the lanes snap them, halves included.
  for (int i = 0; i < 2000; ++i) {
    Triangle t;
    for (auto& v : t) {
      v = i % 2 == 0 ? glm::dvec2{random.real(-6, 46), random.real(-6, 46)}
                     : glm::dvec2{(random.integer(-1500, 12000) + 0.5) / 256,
                                  (random.integer(-1500, 12000) + 0.5) / 256};
    }
    shapes.push_back(t);
  }
  const std::vector<SceneTriangle> triangles = in_every_vertex_order(shapes);
  LaneCounts counts;
  for (const int group : {8, 5, 1}) {
    check_lanes(triangles, 45, 37, group, counts);
    check_lanes(triangles, 21, 19, group, counts);
  }
  // Both paths and the cull were taken many times.
  CHECK(counts.set_up > 50000);
  CHECK(counts.nothing > 10000);
  CHECK(counts.scalar > 5000);
}

TEST_CASE("The lanes set up a jittered mesh's triangles as setup_triangle does",
          "[08_fast_exact][step10]") {
  tri::testing::Random random(224);
  std::vector<SceneTriangle> mesh;
  for (const Triangle& t : jittered_mesh(random, 40, 2.3)) mesh.push_back({t});
  LaneCounts counts;
  check_lanes(mesh, 100, 100, tri::ch08::setup_lanes, counts);
  check_lanes(in_every_vertex_order({mesh[0].vertices, mesh[1].vertices, mesh[777].vertices}), 90,
              80, tri::ch08::setup_lanes, counts);
  CHECK(counts.set_up > 3000);
  CHECK(counts.scalar == 0);
}

TEST_CASE("Lanes at the coordinate bound are set up in lanes, beyond it by the scalar setup",
          "[08_fast_exact][step10]") {
  const double bound = tri::ch08::max_lane_coordinate;
  const double past = bound + 1.0 / 256;  // the next point of the 1/256 grid
  const double far = 1073741824.0;        // 2^30, the largest coordinate a scene may hold
  const std::vector<Triangle> at_bound{
      // The largest numbers the lanes form: vertices on the bound around the largest canvas.
      {{{-bound, -bound}, {bound, -bound}, {-bound, bound}}},
      {{{bound, bound}, {-bound, bound}, {bound, -bound}}},
      {{{-bound, 3.5}, {16383.25, -bound}, {bound, bound}}},
      {{{bound, 0}, {0, bound}, {-bound, -bound + 1.0 / 256}}},
      // Off the canvas, zero area, clockwise.
      {{{-bound, -bound}, {-bound + 5, -bound}, {-bound, -bound + 5}}},
      {{{-3, -3}, {-1, -3}, {-2, -1}}},
      {{{0, 3}, {7, 3}, {3, 3}}},
      {{{0.5, 0.5}, {0.5, 0.5}, {0.75, 0.5}}},
      {{{1, 1}, {2, 9}, {9, 2}}},
      {{{16383.5, 16383.5}, {16382, 16383.75}, {16383.75, 16382}}},
  };
  const std::vector<Triangle> beyond{
      {{{-past, 0}, {10, 0}, {0, 10}}},        {{{0, 0}, {10, past}, {0, 10}}},
      {{{-far, -far}, {far, -far}, {0, far}}}, {{{-far, far}, {far, far}, {far, -far}}},
      {{{1e7, 1e7}, {-1e7, 1e7}, {0, -1e7}}},  {{{far, far}, {far - 1, far}, {far, far - 1}}},
      {{{2.5, 3.5}, {-far, 7.25}, {9, far}}},
  };
  for (const auto& [width, height] : {std::array{16384, 16384}, std::array{40, 30}}) {
    LaneCounts counts;
    check_lanes(in_every_vertex_order(at_bound), width, height, tri::ch08::setup_lanes, counts);
    CHECK(counts.scalar == 0);
    CHECK(counts.set_up >= 24);
    LaneCounts fallback;
    // Mixed into groups with triangles set up in lanes, so both paths share a pass.
    std::vector<Triangle> mixed;
    for (std::size_t i = 0; i < beyond.size(); ++i) {
      mixed.push_back(beyond[i]);
      mixed.push_back(at_bound[i]);
    }
    check_lanes(in_every_vertex_order(mixed), width, height, tri::ch08::setup_lanes, fallback);
    CHECK(fallback.scalar == 2 * 6 * static_cast<int>(beyond.size()));  // two instruction sets
  }
}

TEST_CASE("The batched entry draws exactly fast_hybrid's pixels, overlapping colours included",
          "[08_fast_exact][step10]") {
  // Scenes of every shape in many colours, a later triangle painting over earlier ones, in
  // counts that leave a partial group of lanes; and a jittered mesh in colours.
  for (const int count : {0, 1, 7, 8, 9, 300, 1001}) {
    const auto scene =
        tri::ch08::testing::overlapping_scene(static_cast<std::uint64_t>(count) + 5, count, 50);
    for (const bool counting : {false, true}) {
      INFO(count << " triangles, counting " << counting);
      const Canvas batched = drawn_batch(tri::ch08::draw_batch_batched, scene, 50, 47, counting);
      const Canvas hybrid = drawn_batch(tri::ch08::draw_batch_hybrid, scene, 50, 47, counting);
      CHECK(tri::ch08::testing::same_canvas(batched, hybrid));
      CHECK(batched.outside_writes() == 0);
    }
  }
  tri::testing::Random random(12);
  std::vector<SceneTriangle> mesh;
  for (const Triangle& t : jittered_mesh(random, 30, 3.1)) {
    mesh.push_back({t, tri::Color{static_cast<std::uint8_t>(mesh.size()),
                                  static_cast<std::uint8_t>(mesh.size() / 256), 77, 255}});
  }
  for (const bool counting : {false, true}) {
    const Canvas batched = drawn_batch(tri::ch08::draw_batch_batched, mesh, 97, 83, counting);
    const Canvas hybrid = drawn_batch(tri::ch08::draw_batch_hybrid, mesh, 97, 83, counting);
    CHECK(tri::ch08::testing::same_canvas(batched, hybrid));
  }
}

TEST_CASE("On a canvas larger than 1024x1024 the batched entry draws through tiles the same pixels",
          "[08_fast_exact][step10]") {
  // Just above and at the bounds: 1100 x 1000 pixels (tiled from 64 triangles on), 1024 x 1024
  // (never tiled); overlapping colours over many tiles, and write counts.
  for (const auto& [width, height] : {std::pair{1100, 1000}, std::pair{1024, 1024}}) {
    for (const int count : {63, 64, 400}) {
      const auto scene = tri::ch08::testing::overlapping_scene(
          static_cast<std::uint64_t>(count + width), count, width);
      for (const bool counting : {false, true}) {
        INFO(width << "x" << height << ", " << count << " triangles, counting " << counting);
        const Canvas batched =
            drawn_batch(tri::ch08::draw_batch_batched, scene, width, height, counting);
        const Canvas hybrid =
            drawn_batch(tri::ch08::draw_batch_hybrid, scene, width, height, counting);
        CHECK(tri::ch08::testing::same_canvas(batched, hybrid));
        CHECK(batched.outside_writes() == 0);
      }
    }
  }
}

TEST_CASE("The batched narrow draw writes the oracle's pixels into one byte and one bit per pixel",
          "[08_fast_exact][step10][step8]") {
  // Overlapping triangles of every shape (later over earlier in index8), groups cut short at the
  // batch's end, with the lanes' portable copy and the widest the host runs.
  const auto portable = [](tri::NarrowTarget& target, std::span<const SceneTriangle> triangles) {
    tri::ch08::draw_narrow_batched_with(target, triangles, tri::ch08::InstructionSet::portable);
  };
  int drawn = 0;
  for (const auto& [count, width, height] :
       std::vector<std::array<int, 3>>{{300, 130, 61}, {13, 45, 37}, {700, 21, 19}}) {
    CAPTURE(count, width, height);
    const auto scene = tri::ch08::testing::overlapping_scene(static_cast<std::uint64_t>(count),
                                                             count, std::max(width, height));
    for (const tri::DrawNarrowFunction draw :
         {tri::DrawNarrowFunction{portable}, &tri::ch08::draw_narrow_batched}) {
      CHECK(tri::ch08::testing::narrow_pixels_off_oracle(draw, scene, width, height, drawn) == 0);
    }
  }
  CHECK(drawn > 10000);
}
