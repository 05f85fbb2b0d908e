// The exercises' tests: a learner's solution in exercises.cpp passes them as the reference does.
#include "chapters/09_anti_aliasing/exercises.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "chapters/09_anti_aliasing/area_oracle.hpp"
#include "chapters/09_anti_aliasing/test_triangles.hpp"

namespace tri::ch09::exercises {

TEST_CASE("Exercise 1: coverages composited over give 1 - (1 - c1)(1 - c2)..., never below 1 - 1/e",
          "[09_anti_aliasing][step5]") {
  CHECK(composite_over(std::vector<double>{0.5, 0.5}) == 0.75);
  CHECK(composite_over(std::vector<double>{1.0 / 3, 1.0 / 3, 1.0 / 3}) ==
        Approx(1 - 8.0 / 27).epsilon(1e-12));
  CHECK(composite_over(std::vector<double>{0.25, 1.0}) == 1.0);
  CHECK(composite_over(std::vector<double>{}) == 0.0);
  // n equal parts of a pixel: 1 - (1 - 1/n)^n falls towards 1 - 1/e and stays above it.
  for (const int n : {2, 3, 16, 256, 4096}) {
    const std::vector<double> parts(static_cast<std::size_t>(n), 1.0 / n);
    INFO(n << " parts");
    CHECK(composite_over(parts) == Approx(1 - std::pow(1 - 1.0 / n, n)).epsilon(1e-9));
    CHECK(composite_over(parts) > 1 - std::exp(-1.0));
  }
}

TEST_CASE(
    "Exercise 2: sRGB stores linear 0.5 as 188 of 255, so a half-covered black-on-white "
    "edge is 188, not 128",
    "[09_anti_aliasing][step5]") {
  CHECK(srgb_encode(0) == 0);
  CHECK(srgb_encode(1) == Approx(1).epsilon(1e-12));
  CHECK(std::lround(255 * srgb_encode(0.5)) == 188);
  CHECK(std::lround(255 * srgb_encode(0.216)) == 128);  // what 128 really means: 22% of the light
  CHECK(srgb_encode(0.002) == Approx(12.92 * 0.002).epsilon(1e-12));  // the linear toe
  // Continuous where the two pieces meet, and rising everywhere.
  CHECK(srgb_encode(0.0031308) ==
        Approx(1.055 * std::pow(0.0031308, 1 / 2.4) - 0.055).margin(1e-6));
  for (int k = 0; k < 1000; ++k) CHECK(srgb_encode(k / 1000.0) < srgb_encode((k + 1) / 1000.0));
}

TEST_CASE(
    "Exercise 3: a tent filter of radius 1 weighs an edge 1/8 half a pixel off the centre, "
    "the box 0",
    "[09_anti_aliasing][step1]") {
  CHECK(tent_filtered_edge(-2) == 0);
  CHECK(tent_filtered_edge(-1) == 0);
  CHECK(tent_filtered_edge(-0.5) == 0.125);
  CHECK(tent_filtered_edge(0) == 0.5);
  CHECK(tent_filtered_edge(0.5) == 0.875);
  CHECK(tent_filtered_edge(1) == 1);
  CHECK(tent_filtered_edge(3) == 1);
  for (int k = -20; k <= 20; ++k) {  // the two sides of an edge share the pixel
    const double d = k / 16.0;
    CHECK(tent_filtered_edge(d) + tent_filtered_edge(-d) == Approx(1).epsilon(1e-12));
  }
}

TEST_CASE(
    "Exercise 4: where two shapes overlap, non-zero fills once, even-odd leaves a hole, a sum "
    "counts twice",
    "[09_anti_aliasing][step2]") {
  const Triangle a = {{{-4, -4}, {4, -4}, {-4, 4}}};         // counter-clockwise
  const Triangle b = {{{-3, -3}, {5, -3}, {-3, 5}}};         // counter-clockwise, overlapping a
  const Triangle reversed = {{{-3, -3}, {-3, 5}, {5, -3}}};  // b wound clockwise
  const SamplePattern pattern = regular_grid(4);
  const std::vector<Triangle> same_way = {a, b}, opposite = {a, reversed};
  using enum FillRule;
  // Pixel (-1, -1) lies inside both.
  CHECK(fill_rule_coverage(same_way, {-1, -1}, pattern, non_zero) == 1);
  CHECK(fill_rule_coverage(same_way, {-1, -1}, pattern, even_odd) == 0);
  CHECK(sampled_coverage(a, {-1, -1}, pattern) + sampled_coverage(b, {-1, -1}, pattern) == 2);
  // Wound against each other, the windings cancel: non-zero leaves the overlap empty too.
  CHECK(fill_rule_coverage(opposite, {-1, -1}, pattern, non_zero) == 0);
  // Across a's long edge x + y = 0, pixel (0, 0) is half in a, wholly in b: non-zero 1, even-odd
  // the half outside a, the sum 1.5.
  CHECK(fill_rule_coverage(same_way, {0, 0}, pattern, non_zero) == 1);
  CHECK(fill_rule_coverage(same_way, {0, 0}, pattern, even_odd) ==
        1 - sampled_coverage(a, {0, 0}, pattern));
  CHECK(sampled_coverage(a, {0, 0}, pattern) + sampled_coverage(b, {0, 0}, pattern) > 1);
  // Pixel (4, -3) lies inside b alone: every rule gives b's own coverage.
  for (const FillRule rule : {non_zero, even_odd}) {
    CHECK(fill_rule_coverage(same_way, {4, -3}, pattern, rule) ==
          sampled_coverage(b, {4, -3}, pattern));
  }
  CHECK(sampled_coverage(b, {4, -3}, pattern) > 0);
  CHECK(sampled_coverage(a, {4, -3}, pattern) == 0);
}

TEST_CASE(
    "Exercise 5: font-rs's accumulation buffer, summed along the row, gives every pixel its "
    "exact coverage",
    "[09_anti_aliasing][step4]") {
  // The triangle of the step 1 and step 4 figures, by hand: pixels 0 to 3 of row 0 hold
  // -1/2, -1/2 + 1/12, 5/12 + 5/12 and 1/12; the running sums are -1/2, -11/12, -1/12 and 0.
  const Triangle figure = {{{-0.5, -1.5}, {2.5, -1.5}, {0.5, 1.5}}};
  const std::vector<Fraction> row = accumulated_row(figure, 0, 5);
  REQUIRE(row.size() == 5);
  CHECK(row[0] == Fraction(1, 2));
  CHECK(row[1] == Fraction(11, 12));
  CHECK(row[2] == Fraction(1, 12));
  CHECK(row[3] == Fraction(0));
  for (const Triangle& random : test::random_triangles(40, 44, {1, 1}, {9, 9})) {
    const glm::dvec2 ab = random[1] - random[0], ac = random[2] - random[0];
    const Triangle t =
        ab.x * ac.y - ab.y * ac.x >= 0 ? random : Triangle{{random[0], random[2], random[1]}};
    for (int y = 0; y <= 10; ++y) {
      const std::vector<Fraction> coverages = accumulated_row(t, y, 11);
      for (int x = 0; x <= 10; ++x) {
        INFO("pixel " << x << ", " << y);
        CHECK(coverages[static_cast<std::size_t>(x)] == exact_coverage(t, {x, y}));
      }
    }
  }
}

}  // namespace tri::ch09::exercises
