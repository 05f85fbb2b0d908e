// What the external peers' tests share: the oracle's counts and small seeded scenes.
#pragma once

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "chapters/10_speed_vs_error/suites.hpp"
#include "common/canvas.hpp"
#include "measure/area_error.hpp"
#include "measure/error_metrics.hpp"
#include "measure/peers/peer.hpp"
#include "measure/registry.hpp"
#include "measure/render_scene.hpp"
#include "measure/scene_generators.hpp"

namespace tri::peers_test {

/// The exact oracle's write counts of the triangles on a width x height canvas.
inline WriteCounts oracle_counts(int width, int height, std::span<const SceneTriangle> triangles) {
  const auto all = registered_algorithms();
  return draw_write_counts(*find_named(all, "exact_oracle"), width, height, triangles);
}

/// 300 seeded triangles of one kind on a 64x48 canvas, vertices on a 1/2^grid_bits grid.
inline Scene small_scene(SceneRecipe::Kind kind, int grid_bits, std::uint64_t seed) {
  SceneRecipe recipe;
  recipe.kind = kind;
  recipe.width = 64;
  recipe.height = 48;
  recipe.triangles = 300;
  recipe.min_extent = 0.5;
  recipe.max_extent = 12;
  recipe.grid_bits = grid_bits;
  recipe.seed = seed;
  return generate_scene(recipe);
}

/// How many pixels two count lists disagree on.
inline std::size_t differing_pixels(const std::vector<std::uint32_t>& a,
                                    const std::vector<std::uint32_t>& b) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) n += a[i] != b[i];
  return n + (a.size() > b.size() ? a.size() - b.size() : b.size() - a.size());
}

/// The distance from pixel centre c to the nearest edge of any of the triangles: exactly 0 when c
/// lies on an edge (the cross product is exact for the suites' 1/256-grid coordinates below 2^15).
inline double nearest_edge_distance(glm::dvec2 c, std::span<const SceneTriangle> triangles) {
  double nearest = std::numeric_limits<double>::infinity();
  for (const SceneTriangle& t : triangles) {
    for (int k = 0; k < 3; ++k) {
      const glm::dvec2 a = t.vertices[k], d = t.vertices[(k + 1) % 3] - a;
      const double length2 = d.x * d.x + d.y * d.y;
      const double along =
          std::clamp(length2 > 0 ? ((c - a).x * d.x + (c - a).y * d.y) / length2 : 0.0, 0.0, 1.0);
      const double cross = d.x * (c - a).y - d.y * (c - a).x;
      // Within the segment the distance is |cross| / length, 0 exactly on the line.
      const double distance = along > 0 && along < 1
                                  ? std::abs(cross) / std::sqrt(length2)
                                  : std::hypot((a + along * d - c).x, (a + along * d - c).y);
      nearest = std::min(nearest, distance);
    }
  }
  return nearest;
}

/// The prepared scene of the quick suite (the report's default) with this name and grid.
inline PreparedScene quick_scene(const std::string& name, const std::string& grid) {
  const auto settings = ch10::bench_settings(ch10::SuiteSize::quick);
  const auto suite = std::find_if(settings.scenes.begin(), settings.scenes.end(),
                                  [&](auto& s) { return s.name == name && s.grid == grid; });
  REQUIRE(suite != settings.scenes.end());
  return prepare_scene(*suite, 0);
}

/// Where a peer's write counts differ from the oracle's on one scene: missed and extra writes, and
/// the distance from each differing pixel's centre to the nearest edge of any triangle.
struct Differences {
  std::uint64_t missed = 0, extra = 0;
  std::vector<double> edge_distances;
};

inline Differences differences_from_oracle(const CountingDraw& write_counts, int width, int height,
                                           std::span<const SceneTriangle> triangles) {
  const auto drawn = write_counts(width, height, triangles).counts;
  const auto truth = oracle_counts(width, height, triangles).counts;
  Differences d;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const std::size_t i = pixel_index(x, y, width);
      if (drawn[i] == truth[i]) continue;
      d.missed += truth[i] > drawn[i] ? truth[i] - drawn[i] : 0;
      d.extra += drawn[i] > truth[i] ? drawn[i] - truth[i] : 0;
      d.edge_distances.push_back(nearest_edge_distance({x, y}, triangles));
    }
  }
  return d;
}

/// A square from (1, 1) to (6, 6) in two triangles on an 8x8 canvas: 5x5 pixel centres inside
/// or on its border, each owned once by an exact rule.
inline std::vector<SceneTriangle> split_square() {
  return {{{{{1, 1}, {6, 1}, {1, 6}}}, colors::white}, {{{{6, 1}, {6, 6}, {1, 6}}}, colors::white}};
}

/// An anti-aliasing peer measured on a scene (one untimed-looking sample: the tests never time):
/// its touched pixels and its error against the exact area.
inline CoveragePeerResult measure_coverage_peer(const CoveragePeer& peer, const Scene& scene) {
  PreparedScene prepared;
  prepared.suite.name = "test";
  prepared.suite.grid = "1/256";
  prepared.scene = scene;
  prepared.triangles = scene_triangles(scene);
  prepared.error_scene = scene;
  return peer.measure(prepared, AreaTruth(scene), TimingPlan{0.0, 1, 1});
}

/// An anti-aliasing peer on small_scene's 300 random triangles of the 1/2^grid_bits grid, each
/// of them compared with the exact area (none refused).
inline CoveragePeerResult on_random_triangles(const CoveragePeer& peer, int grid_bits,
                                              std::uint64_t seed) {
  const CoveragePeerResult r =
      measure_coverage_peer(peer, small_scene(SceneRecipe::Kind::random, grid_bits, seed));
  CHECK(r.error.triangles == 300);
  CHECK(r.error.pixels > 1000);
  CHECK(r.touched_pixels > 0);
  return r;
}

/// An area peer that keeps its coverage in 8 bits, on 300 random triangles of each grid: within
/// `bound` of the exact area on every pixel, yet more than one 8-bit step (1/255) off somewhere.
inline void check_eight_bit_area(const CoveragePeer& peer, std::initializer_list<int> grids,
                                 std::uint64_t seed, double bound) {
  for (const int grid_bits : grids) {
    INFO("grid 1/2^" << grid_bits);
    const auto r = on_random_triangles(peer, grid_bits, seed);
    CHECK(r.error.max <= bound);
    CHECK(r.error.max > 1.0 / 255);
    CHECK(r.error.mean > 0);
  }
}

}  // namespace tri::peers_test
