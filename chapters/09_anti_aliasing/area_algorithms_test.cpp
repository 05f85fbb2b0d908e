#include "chapters/09_anti_aliasing/area_algorithms.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "chapters/09_anti_aliasing/area_oracle.hpp"
#include "chapters/09_anti_aliasing/sample_spans.hpp"
#include "chapters/09_anti_aliasing/sampling.hpp"
#include "chapters/09_anti_aliasing/test_triangles.hpp"

namespace tri::ch09 {
namespace {

// Random triangles reaching a little past a 16 x 12 canvas on every side.
std::vector<Triangle> random_triangles(int count, std::uint64_t seed) {
  return test::random_triangles(count, seed, {-2, -2}, {18, 14});
}

std::vector<SamplePattern> every_pattern() {
  std::vector<SamplePattern> patterns;
  for (const int n : {1, 2, 4, 8, 16}) patterns.push_back(regular_grid(n));
  for (const int count : {2, 4, 8, 16}) patterns.push_back(standard_pattern(count));
  return patterns;
}

}  // namespace

TEST_CASE("draw_triangle_samples gives every pixel exactly the value sampled_coverage gives",
          "[09_anti_aliasing][step3]") {
  for (const SamplePattern& pattern : every_pattern()) {
    for (const Triangle& t : random_triangles(40, 7)) {
      INFO(pattern.name << " on (" << t[0].x << ", " << t[0].y << ") (" << t[1].x << ", " << t[1].y
                        << ") (" << t[2].x << ", " << t[2].y << ")");
      CoverageCanvas canvas(16, 12);
      draw_triangle_samples(canvas, t, pattern);
      int mismatches = 0;
      for (int y = 0; y < canvas.height(); ++y) {
        for (int x = 0; x < canvas.width(); ++x) {
          // Every weight is a power of two: the sums are exact, so equality is the claim.
          mismatches += canvas.at(x, y) != static_cast<float>(sampled_coverage(t, {x, y}, pattern));
        }
      }
      CHECK(mismatches == 0);
    }
  }
}

TEST_CASE("exact_coverages agrees with exact_coverage on every pixel around the triangle",
          "[09_anti_aliasing][step1]") {
  for (const Triangle& t : random_triangles(60, 8)) {
    const auto listed = exact_coverages(t);
    std::size_t k = 0;
    for (int y = -4; y <= 16; ++y) {
      for (int x = -4; x <= 20; ++x) {
        const Fraction expected = exact_coverage(t, {x, y});
        if (k < listed.size() && listed[k].pixel == glm::ivec2{x, y}) {
          CHECK(listed[k].coverage == expected);
          ++k;
        } else {
          CHECK(expected == Fraction(0));
        }
      }
    }
    CHECK(k == listed.size());
  }
}

TEST_CASE("The registered coverage algorithms have rule area, unique names and their sample counts",
          "[09_anti_aliasing][registry]") {
  const auto algorithms = area_algorithms();
  REQUIRE(algorithms.size() == 11);
  std::vector<std::string> names;
  for (const AreaAlgorithm& a : algorithms) {
    INFO(a.name);
    CHECK(a.rule == CoverageRule::area);
    CHECK(a.chapter == "09_anti_aliasing");
    CHECK(!a.summary.empty());
    for (const auto& n : names) CHECK(n != a.name);
    names.emplace_back(a.name);
  }
  CHECK(algorithms[0].name == "area_cells");
  CHECK(algorithms[0].samples == 0);
  CHECK(algorithms[0].sample_pattern == nullptr);
  CHECK(algorithms[1].sample_pattern == nullptr);
  CHECK(algorithms[4].name == "samples_grid_4x4");
  CHECK(algorithms[4].samples == 16);
  CHECK(algorithms[10].name == "samples_standard_16");
  CHECK(algorithms[10].samples == 16);
}

TEST_CASE("Each sampling algorithm draws a scene as its pattern sampled pixel by pixel, summed",
          "[09_anti_aliasing][step3]") {
  const auto triangles = random_triangles(6, 9);
  std::vector<SceneTriangle> scene;
  for (const Triangle& t : triangles) scene.push_back({t});
  for (const AreaAlgorithm& algorithm : area_algorithms()) {
    if (algorithm.samples == 0) continue;
    INFO(algorithm.name);
    const std::string pattern_name(algorithm.name.substr(std::string_view("samples_").size()));
    SamplePattern pattern;
    for (const auto& p : every_pattern()) {
      if (p.name == pattern_name) pattern = p;
    }
    REQUIRE(pattern.offsets.size() == static_cast<std::size_t>(algorithm.samples));
    REQUIRE(algorithm.sample_pattern != nullptr);
    CHECK(algorithm.sample_pattern().offsets == pattern.offsets);
    CoverageCanvas canvas(16, 12);
    CHECK(draw_coverage(algorithm, canvas, scene) == 0);
    int mismatches = 0;
    for (int y = 0; y < canvas.height(); ++y) {
      for (int x = 0; x < canvas.width(); ++x) {
        double sum = 0;
        for (const Triangle& t : triangles) sum += sampled_coverage(t, {x, y}, pattern);
        mismatches += std::abs(canvas.at(x, y) - sum) > 1e-6;
      }
    }
    CHECK(mismatches == 0);
  }
}

TEST_CASE("draw_coverage refuses a non-finite or out-of-range triangle and draws the others",
          "[09_anti_aliasing][registry]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<SceneTriangle> scene = {
      {{{{1, 1}, {9, 1}, {1, 9}}}},
      {{{{nan, 1}, {9, 1}, {1, 9}}}},
      {{{{1, 1}, {1e12, 1}, {1, 9}}}},
  };
  for (const AreaAlgorithm& algorithm : area_algorithms()) {
    INFO(algorithm.name);
    CoverageCanvas with_bad(12, 12), alone(12, 12);
    CHECK(draw_coverage(algorithm, with_bad, scene) == 2);
    CHECK(draw_coverage(algorithm, alone, std::span(scene).first(1)) == 0);
    int differences = 0;
    for (int y = 0; y < 12; ++y) {
      for (int x = 0; x < 12; ++x) differences += with_bad.at(x, y) != alone.at(x, y);
    }
    CHECK(differences == 0);
    CHECK(alone.at(3, 3) == 1.0f);
  }
}

}  // namespace tri::ch09
