#include <bit>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <variant>

#include <catch2/catch.hpp>
#include <glm/common.hpp>

#include "measure/scene_generators.hpp"

using tri::generate_scene;
using tri::Scene;
using tri::SceneRecipe;
using tri::SceneTriangle;

namespace {

// FNV-1a over every vertex coordinate's eight bytes (lowest first, whatever the machine's byte
// order) and every colour channel: two compilers that draw in different orders get different
// values.
std::uint64_t scene_hash(const Scene& scene) {
  std::uint64_t hash = 0xcbf29ce484222325u;
  const auto add_byte = [&](std::uint64_t byte) {
    hash = (hash ^ (byte & 0xffu)) * 0x100000001b3u;
  };
  for (const auto& primitive : scene.primitives) {
    const auto& t = std::get<SceneTriangle>(primitive);
    for (const auto& v : t.vertices) {
      for (const double coordinate : {v.x, v.y}) {
        const auto bits = std::bit_cast<std::uint64_t>(coordinate);
        for (int shift = 0; shift < 64; shift += 8) add_byte(bits >> shift);
      }
    }
    for (int channel = 0; channel < 4; ++channel) add_byte(t.color[channel]);
  }
  return hash;
}

SceneRecipe recipe(SceneRecipe::Kind kind, int grid_bits, std::uint64_t seed) {
  return {.kind = kind,
          .width = 256,
          .height = 192,
          .triangles = 500,
          .min_extent = 1,
          .max_extent = 20,
          .grid_bits = grid_bits,
          .seed = seed};
}

}  // namespace

// The values were computed once; every compiler must draw the same numbers in the same order,
// or the quoted error counts and golden figures would depend on the compiler.
TEST_CASE("Every scene family draws the same vertices and colours from every compiler",
          "[measure][scenes]") {
  using Kind = SceneRecipe::Kind;
  CHECK(scene_hash(generate_scene(recipe(Kind::random, 8, 1))) == 0xb736fe615db74772u);
  CHECK(scene_hash(generate_scene(recipe(Kind::random, 0, 7))) == 0xc34658a33580c379u);
  CHECK(scene_hash(generate_scene(recipe(Kind::slivers, 8, 2))) == 0x8fff1938701b95b6u);
  CHECK(scene_hash(generate_scene(recipe(Kind::fan, 8, 3))) == 0xf5b9055a2683cc9au);
  CHECK(scene_hash(generate_scene(recipe(Kind::jittered_grid, 8, 4))) == 0x2be5ff47f5f49ed3u);
  CHECK(scene_hash(generate_scene(recipe(Kind::in_boxes, 8, 5))) == 0x901f798b040f1759u);
}

TEST_CASE("A random scene keeps only triangles within the asked areas", "[measure][scenes]") {
  SceneRecipe r = recipe(SceneRecipe::Kind::random, 8, 5);
  r.min_area = 4;
  r.max_area = 30;
  const Scene scene = generate_scene(r);
  REQUIRE(scene.primitives.size() == 500u);
  for (const auto& primitive : scene.primitives) {
    const auto& [a, b, c] = std::get<SceneTriangle>(primitive).vertices;
    const double area = std::abs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)) / 2;
    CHECK(area >= 4);
    CHECK(area <= 30);
  }
}

// Blend2D's bl_bench FillTriangle shape: three points in a box_side square, the square anywhere
// on the canvas. On the 1/256 grid a vertex moves at most half a step when snapped.
TEST_CASE("A boxed scene keeps each triangle within its square, inside the canvas, seeded",
          "[measure][scenes]") {
  for (const double side : {8.0, 64.0, 256.0}) {
    const SceneRecipe r{.kind = SceneRecipe::Kind::in_boxes,
                        .width = 512,
                        .height = 600,
                        .triangles = 300,
                        .box_side = side,
                        .seed = 11};
    const Scene scene = generate_scene(r);
    REQUIRE(scene.primitives.size() == 300u);
    double widest = 0;
    for (const auto& primitive : scene.primitives) {
      const auto& vertices = std::get<SceneTriangle>(primitive).vertices;
      glm::dvec2 low = vertices[0], high = vertices[0];
      for (const auto& v : vertices) {
        CHECK(v.x >= 0);
        CHECK(v.x <= 512);
        CHECK(v.y >= 0);
        CHECK(v.y <= 600);
        CHECK(v.x * 256 == std::floor(v.x * 256));
        low = glm::min(low, v);
        high = glm::max(high, v);
      }
      CHECK(high.x - low.x <= side + 1.0 / 256);
      CHECK(high.y - low.y <= side + 1.0 / 256);
      widest = std::max({widest, high.x - low.x, high.y - low.y});
    }
    CHECK(widest > side * 0.9);  // the squares are filled, not just a corner of them
    CHECK(scene_hash(generate_scene(r)) == scene_hash(scene));
    SceneRecipe other = r;
    other.seed = 12;
    CHECK(scene_hash(generate_scene(other)) != scene_hash(scene));
  }
}
