#include "chapters/09_anti_aliasing/sampling.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <utility>
#include <vector>

#include "chapters/09_anti_aliasing/area_oracle.hpp"
#include "chapters/09_anti_aliasing/coverage_error.hpp"
#include "chapters/09_anti_aliasing/test_triangles.hpp"

#include <glm/common.hpp>

namespace tri::ch09 {

namespace {

// Random triangles inside a 12 x 12 pixel area.
std::vector<Triangle> random_triangles(int count, std::uint64_t seed) {
  return test::random_triangles(count, seed, {0, 0}, {12, 12});
}

// The least-squares slope of y against x.
double slope(const std::vector<double>& x, const std::vector<double>& y) {
  const auto n = static_cast<double>(x.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sx += x[i];
    sy += y[i];
    sxx += x[i] * x[i];
    sxy += x[i] * y[i];
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

PixelCoverageFunction with(const SamplePattern& pattern) {
  return [pattern](const Triangle& t, glm::ivec2 p) { return sampled_coverage(t, p, pattern); };
}

}  // namespace

TEST_CASE("A regular grid has n x n distinct samples inside the pixel, centred on its centre",
          "[09_anti_aliasing][step2]") {
  for (const int n : {1, 2, 4, 8, 16}) {
    const SamplePattern grid = regular_grid(n);
    INFO(grid.name);
    REQUIRE(grid.offsets.size() == static_cast<std::size_t>(n * n));
    std::set<std::pair<int, int>> distinct;
    glm::ivec2 sum{0, 0};
    for (const auto o : grid.offsets) {
      CHECK(o.x >= -16);
      CHECK(o.x < 16);
      CHECK(o.y >= -16);
      CHECK(o.y < 16);
      distinct.insert({o.x, o.y});
      sum += o;
    }
    CHECK(distinct.size() == grid.offsets.size());
    CHECK(sum == glm::ivec2{0, 0});
  }
  CHECK(regular_grid(1).offsets.front() == glm::ivec2{0, 0});  // one sample: the centre
  CHECK_THROWS(regular_grid(3));
}

TEST_CASE("A standard pattern puts no two samples in one row or one column",
          "[09_anti_aliasing][step3]") {
  for (const int count : {2, 4, 8, 16}) {
    const SamplePattern pattern = standard_pattern(count);
    INFO(pattern.name);
    REQUIRE(pattern.offsets.size() == static_cast<std::size_t>(count));
    std::set<int> xs, ys;
    for (const auto o : pattern.offsets) {
      CHECK(o.x >= -16);
      CHECK(o.x < 16);
      CHECK(o.y > -16);
      CHECK(o.y <= 16);
      xs.insert(o.x);
      ys.insert(o.y);
    }
    CHECK(xs.size() == pattern.offsets.size());
    CHECK(ys.size() == pattern.offsets.size());
  }
  CHECK_THROWS(standard_pattern(3));
}

TEST_CASE("With one sample per pixel, coverage is chapter 07's yes or no at the centre",
          "[09_anti_aliasing][step2]") {
  const Triangle t = {{{0.5, 0.5}, {9.25, 2}, {3, 8.75}}};
  for (int y = -1; y <= 10; ++y) {
    for (int x = -1; x <= 10; ++x) {
      const double c = sampled_coverage(t, {x, y}, regular_grid(1));
      CHECK((c == 0.0 || c == 1.0));
    }
  }
  CHECK(sampled_coverage(t, {3, 3}, regular_grid(1)) == 1.0);
  CHECK(sampled_coverage(t, {9, 8}, regular_grid(1)) == 0.0);
}

TEST_CASE("In a mesh every sample is counted once, so sampled coverages add up to exactly one",
          "[09_anti_aliasing][step2]") {
  // Two triangles sharing a diagonal that passes through samples of the 4x4 grid.
  const Triangle lower = {{{-2, -2}, {2, -2}, {2, 2}}};
  const Triangle upper = {{{-2, -2}, {2, 2}, {-2, 2}}};
  for (const auto& pattern : {regular_grid(4), regular_grid(16), standard_pattern(8)}) {
    for (int y = -1; y <= 1; ++y) {
      for (int x = -1; x <= 1; ++x) {
        INFO(pattern.name << " pixel " << x << ", " << y);
        CHECK(sampled_coverage(lower, {x, y}, pattern) + sampled_coverage(upper, {x, y}, pattern) ==
              1.0);
      }
    }
  }
}

TEST_CASE("The mean error of a regular grid falls as about n^-1.5, the worst within 3/n",
          "[09_anti_aliasing][step2]") {
  // Along an edge each of the n sample rows is off by at most one sample (1/n^2 of the pixel), so
  // a pixel crossed by at most three edges is off by at most 3/n; the rows' errors have random
  // signs and partly cancel, so the mean falls faster, as about sqrt(n)/n^2 = n^-1.5.
  const auto triangles = random_triangles(40, 2026);
  // The README's table, to its three significant digits.
  const std::array<std::pair<double, double>, 5> printed = {
      {{0.170, 0.986}, {0.0639, 0.444}, {0.0220, 0.141}, {0.00761, 0.0671}, {0.00217, 0.0180}}};
  std::vector<double> log_n, log_mean;
  for (const int n : {1, 2, 4, 8, 16}) {
    const auto error = coverage_error(triangles, with(regular_grid(n)));
    INFO("grid " << n << "x" << n << ": mean " << error.mean << ", max " << error.max);
    CHECK(error.max <= 3.0 / n);
    const auto [mean, max] = printed[log_n.size()];
    CHECK(error.mean == Approx(mean).epsilon(0.005));
    CHECK(error.max == Approx(max).epsilon(0.005));
    log_n.push_back(std::log2(n));
    log_mean.push_back(std::log2(error.mean));
  }
  const double mean_slope = slope(log_n, log_mean);
  INFO("slope of log mean error against log n: " << mean_slope);
  CHECK(mean_slope == Approx(-1.57).margin(0.005));
  CHECK(mean_slope < -1.3);
  CHECK(mean_slope > -1.7);
}

TEST_CASE("On random triangles the 4x4 grid has less mean error than the standard 16 pattern",
          "[09_anti_aliasing][step3]") {
  const auto triangles = random_triangles(40, 7);
  const auto grid = coverage_error(triangles, with(regular_grid(4)));
  const auto rotated = coverage_error(triangles, with(standard_pattern(16)));
  INFO("4x4 grid mean " << grid.mean << " max " << grid.max << "; standard 16 mean " << rotated.mean
                        << " max " << rotated.max);
  CHECK(grid.mean < rotated.mean);
}

TEST_CASE("Within 2 degrees of an axis the standard patterns beat grids of as many samples",
          "[09_anti_aliasing][step3]") {
  // Squares turned by 0 to 2 degrees, cut in two: their edges nearly follow the pixel rows and
  // columns, where a grid's samples line up in n columns and a standard pattern's in n * n.
  Random random(11);
  std::vector<Triangle> triangles;
  for (int k = 0; k < 40; ++k) {
    const double angle = 2 * random.real(0, 1) * 3.14159265358979 / 180;
    const glm::dvec2 u{std::cos(angle) * 8, std::sin(angle) * 8}, v{-u.y, u.x};
    const glm::dvec2 o{2 + random.real(0, 1), 1 + random.real(0, 1)};
    const auto on_grid = [](glm::dvec2 p) { return glm::round(p * 256.0) / 256.0; };
    triangles.push_back({{on_grid(o), on_grid(o + u), on_grid(o + u + v)}});
    triangles.push_back({{on_grid(o), on_grid(o + u + v), on_grid(o + v)}});
  }
  for (const int n : {2, 4}) {
    const auto grid = coverage_error(triangles, with(regular_grid(n)));
    const auto rotated = coverage_error(triangles, with(standard_pattern(n * n)));
    INFO(n << "x" << n << " grid mean " << grid.mean << " max " << grid.max << "; standard "
           << n * n << " mean " << rotated.mean << " max " << rotated.max);
    CHECK(rotated.mean < grid.mean);
    CHECK(rotated.max < grid.max);
  }
}

}  // namespace tri::ch09
