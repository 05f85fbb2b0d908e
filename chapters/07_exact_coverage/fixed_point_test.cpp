#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "chapters/07_exact_coverage/algorithms.hpp"
#include "chapters/07_exact_coverage/coverage_oracle.hpp"
#include "chapters/07_exact_coverage/fixed_point.hpp"
#include "tests/support/pixels.hpp"

using tri::Triangle;
using tri::ch07::SubpixelPoint;
using tri::testing::PixelSet;

namespace {

using DrawFunction = void (*)(tri::Canvas&, const Triangle&, tri::Color);

PixelSet pixels_of(DrawFunction draw, const Triangle& t, int size = 48) {
  tri::Canvas canvas(size, size);
  canvas.enable_write_counts();
  draw(canvas, t, tri::colors::white);
  REQUIRE(canvas.outside_writes() == 0);
  REQUIRE(tri::testing::overdrawn_pixels(canvas).empty());
  return tri::testing::written_pixels(canvas);
}

// A coordinate on the 1/256 grid in [low, high).
double grid_coordinate(tri::testing::Random& random, double low, double high) {
  return std::floor(random.real(low, high) * 256) / 256;
}

Triangle snapped(const Triangle& t, int bits) {
  Triangle s;
  for (int i = 0; i < 3; ++i) {
    const SubpixelPoint p = tri::ch07::snap_to_subpixel(t[i], bits);
    s[i] = {std::ldexp(static_cast<double>(p.x), -bits),
            std::ldexp(static_cast<double>(p.y), -bits)};
  }
  return s;
}

}  // namespace

TEST_CASE("Snapping rounds to the nearest 1/256 with halves rounding up",
          "[07_exact_coverage][step4]") {
  using tri::ch07::snap_to_subpixel;
  CHECK(snap_to_subpixel({1.0, -1.0}, 8).x == 256);
  CHECK(snap_to_subpixel({1.0, -1.0}, 8).y == -256);
  CHECK(snap_to_subpixel({0.5 / 256, -0.5 / 256}, 8).x == 1);
  CHECK(snap_to_subpixel({0.5 / 256, -0.5 / 256}, 8).y == 0);
  CHECK(snap_to_subpixel({0.49 / 256, 0.51 / 256}, 8).x == 0);
  CHECK(snap_to_subpixel({0.49 / 256, 0.51 / 256}, 8).y == 1);
  CHECK(snap_to_subpixel({1073741824.0, -1073741824.0}, 8).x == std::int64_t{1} << 38);
  CHECK(snap_to_subpixel({2.5, 0}, 0).x == 3);
  // The largest double below one half rounds down: floor(v + 0.5) would give 1, because the sum
  // itself rounds to 1.0.
  CHECK(snap_to_subpixel({0.49999999999999994 / 256, 0.49999999999999994}, 8).x == 0);
  CHECK(snap_to_subpixel({0.49999999999999994, -0.5000000000000001}, 0).x == 0);
  CHECK(snap_to_subpixel({0.49999999999999994, -0.5000000000000001}, 0).y == -1);
}

TEST_CASE("64-bit edge functions are used only while every snapped coordinate is within 2^29",
          "[07_exact_coverage][step5]") {
  using tri::ch07::fits_64_bit_edge_functions;
  const std::int64_t limit = std::int64_t{1} << 29;
  CHECK(fits_64_bit_edge_functions({limit, -limit}, {0, 0}, {-limit, limit}));
  CHECK_FALSE(fits_64_bit_edge_functions({limit + 1, 0}, {0, 0}, {0, 0}));
  CHECK_FALSE(fits_64_bit_edge_functions({0, 0}, {0, -limit - 1}, {0, 0}));
}

TEST_CASE("candidate pixels are the centres within the snapped extent, clipped to the canvas",
          "[07_exact_coverage][step7]") {
  using tri::ch07::candidate_pixels;
  // x from 1.5 to 4 pixels, y from -3 to 2.25 (in 1/256 units).
  const auto r = candidate_pixels({384, -768}, {1024, 0}, {512, 576}, 8, 10, 10);
  CHECK(r.min.x == 2);
  CHECK(r.max.x == 4);
  CHECK(r.min.y == 0);
  CHECK(r.max.y == 2);
  const std::int64_t far = std::int64_t{1} << 38;
  const auto all = candidate_pixels({-far, -far}, {far, -far}, {0, far}, 8, 10, 7);
  CHECK((all.min.x == 0 && all.max.x == 9 && all.min.y == 0 && all.max.y == 6));
  CHECK(candidate_pixels({far, far}, {far, far + 1}, {far + 1, far}, 8, 10, 10).empty());
}

TEST_CASE("The fixed-point rasterizer matches the oracle exactly on the 1/256 grid",
          "[07_exact_coverage][step4]") {
  tri::testing::Random random(2024);
  for (int i = 0; i < 3000; ++i) {
    // Small, medium and slivers, partly off the canvas.
    const double extent = i % 3 == 0 ? 2.0 : (i % 3 == 1 ? 20.0 : 60.0);
    const double cx = random.real(-4, 52), cy = random.real(-4, 52);
    Triangle t;
    for (auto& v : t) {
      v = {grid_coordinate(random, cx - extent, cx + extent),
           grid_coordinate(random, cy - extent, cy + extent)};
    }
    REQUIRE(pixels_of(tri::ch07::draw_triangle_fixed_point_8, t) ==
            pixels_of(tri::ch07::draw_triangle_oracle, t));
  }
}

TEST_CASE("The fixed-point rasterizer matches the oracle for vertices far outside, in 128 bits",
          "[07_exact_coverage][step5]") {
  tri::testing::Random random(99);
  for (int i = 0; i < 200; ++i) {
    Triangle t;
    for (auto& v : t) {
      v = {std::round(random.real(-1073741824.0, 1073741824.0)),
           std::round(random.real(-1073741824.0, 1073741824.0))};
    }
    if (i % 2 == 0) t[0] = {grid_coordinate(random, 0, 48), grid_coordinate(random, 0, 48)};
    REQUIRE(pixels_of(tri::ch07::draw_triangle_fixed_point_8, t) ==
            pixels_of(tri::ch07::draw_triangle_oracle, t));
  }
  const Triangle covering{
      {{-1073741824.0, -1073741824.0}, {1073741824.0, -1073741824.0}, {0, 1073741824.0}}};
  CHECK(pixels_of(tri::ch07::draw_triangle_fixed_point_8, covering).size() == 48 * 48);
}

TEST_CASE("On arbitrary doubles the only deviations are the ones snapping explains",
          "[07_exact_coverage][step4]") {
  tri::testing::Random random(77);
  int differs_from_unsnapped = 0;
  for (int i = 0; i < 2000; ++i) {
    const Triangle t = tri::testing::random_real_triangle(random, -4, 52);
    const PixelSet fixed = pixels_of(tri::ch07::draw_triangle_fixed_point_8, t);
    // Snap first, then ask the oracle: exactly the same pixels.
    REQUIRE(fixed == pixels_of(tri::ch07::draw_triangle_oracle, snapped(t, 8)));
    differs_from_unsnapped += fixed != pixels_of(tri::ch07::draw_triangle_oracle, t);
  }
  // Snapping moves vertices by up to 1/512 pixel per axis, which changes a few triangles' pixels.
  CHECK(differs_from_unsnapped > 0);
  CHECK(differs_from_unsnapped < 2000 / 10);
}

TEST_CASE("Fewer fractional bits snap harder and still follow the top-left rule exactly",
          "[07_exact_coverage][step4]") {
  tri::testing::Random random(4);
  for (const int bits : {0, 2, 4}) {
    for (int i = 0; i < 500; ++i) {
      const Triangle t = tri::testing::random_real_triangle(random, -4, 52);
      tri::Canvas canvas(48, 48);
      canvas.enable_write_counts();
      tri::ch07::draw_triangle_fixed_point(canvas, t, tri::colors::white, bits);
      REQUIRE(tri::testing::written_pixels(canvas) ==
              pixels_of(tri::ch07::draw_triangle_oracle, snapped(t, bits)));
    }
  }
}

TEST_CASE("Zero-area triangles draw nothing and non-finite ones are refused by the entry point",
          "[07_exact_coverage][step4]") {
  CHECK(pixels_of(tri::ch07::draw_triangle_fixed_point_8, {{{0, 0}, {0, 0}, {0, 0}}}).empty());
  CHECK(pixels_of(tri::ch07::draw_triangle_fixed_point_8, {{{1, 1}, {9, 9}, {5, 5}}}).empty());
  // Distinct doubles that snap onto one line cover nothing either.
  CHECK(pixels_of(tri::ch07::draw_triangle_fixed_point_8, {{{1, 1}, {9, 9}, {5, 5 + 1.0 / 1024}}})
            .empty());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const auto& algorithm : tri::ch07::triangle_algorithms()) {
    tri::Canvas canvas(8, 8);
    canvas.enable_write_counts();
    CHECK(tri::draw_triangle(algorithm, canvas, {{{0, 0}, {7, 0}, {nan, 7}}}, tri::colors::white) ==
          tri::DrawResult::rejected_non_finite);
    CHECK(tri::testing::written_pixels(canvas).empty());
  }
}

TEST_CASE("A shared-edge fan is covered exactly once per pixel", "[07_exact_coverage][step4]") {
  // 24 triangles around a centre off the pixel grid, the whole disc exactly once.
  tri::Canvas canvas(48, 48);
  canvas.enable_write_counts();
  const glm::dvec2 centre(23.7, 24.2);
  for (int i = 0; i < 24; ++i) {
    const double a0 = i * 2 * 3.14159265358979 / 24, a1 = (i + 1) * 2 * 3.14159265358979 / 24;
    const Triangle t{{centre, centre + 20.0 * glm::dvec2(std::cos(a0), std::sin(a0)),
                      centre + 20.0 * glm::dvec2(std::cos(a1), std::sin(a1))}};
    tri::ch07::draw_triangle_fixed_point_8(canvas, t, tri::colors::white);
  }
  CHECK(tri::testing::overdrawn_pixels(canvas).empty());
  // No gaps: every pixel within 18 pixels of the centre is drawn.
  for (int y = 0; y < 48; ++y) {
    for (int x = 0; x < 48; ++x) {
      if (glm::length(glm::dvec2(x, y) - centre) < 18) REQUIRE(canvas.write_count(x, y) == 1);
    }
  }
}
