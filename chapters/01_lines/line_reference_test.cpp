// The exact answer the four line algorithms are measured against: the nearest pixel per step.
#include <catch2/catch.hpp>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "chapters/01_lines/line_reference.hpp"
#include "tests/support/pixels.hpp"

using tri::ch01::exact_line_pixel_at;
using tri::ch01::exact_line_pixels;
using tri::ch01::ExactLinePixel;

namespace {

// "(x,y)" per pixel, "~" after a tie: short enough to hand-write, readable when a check fails.
std::string describe(const ExactLinePixel& p) {
  return "(" + std::to_string(p.pixel.x) + "," + std::to_string(p.pixel.y) + ")" +
         (p.tie ? "~" : "");
}

std::string describe(const std::vector<ExactLinePixel>& pixels) {
  std::string text;
  for (const auto& p : pixels) text += (text.empty() ? "" : " ") + describe(p);
  return text;
}

constexpr int two_30 = 1 << 30;

}  // namespace

TEST_CASE("The exact line of a horizontal or vertical segment is its row or column",
          "[01_lines][step1][reference]") {
  CHECK(describe(exact_line_pixels({0, 3}, {5, 3})) == "(0,3) (1,3) (2,3) (3,3) (4,3) (5,3)");
  CHECK(describe(exact_line_pixels({2, -1}, {2, 3})) == "(2,-1) (2,0) (2,1) (2,2) (2,3)");
}

TEST_CASE("The exact line of a single point is that point", "[01_lines][step1][reference]") {
  CHECK(describe(exact_line_pixels({5, 5}, {5, 5})) == "(5,5)");
}

TEST_CASE("The exact line from (0,0) to (4,2) has ties at x = 1 and x = 3, rounded up",
          "[01_lines][step1][reference]") {
  // y = x / 2: at x = 1 and x = 3 the line passes exactly halfway between two rows.
  CHECK(describe(exact_line_pixels({0, 0}, {4, 2})) == "(0,0) (1,1)~ (2,1) (3,2)~ (4,2)");
}

TEST_CASE("The exact line of a steep segment steps along y", "[01_lines][step1][reference]") {
  // x = y / 3: 0, 1/3, 2/3, 1 round to 0, 0, 1, 1.
  CHECK(describe(exact_line_pixels({0, 0}, {1, 3})) == "(0,0) (0,1) (1,2) (1,3)");
  // A 45-degree line counts as x-major (|dx| >= |dy|).
  CHECK(describe(exact_line_pixels({0, 0}, {3, -3})) == "(0,0) (1,-1) (2,-2) (3,-3)");
}

TEST_CASE("The exact line is the same list whichever endpoint comes first",
          "[01_lines][step1][reference]") {
  CHECK(describe(exact_line_pixels({4, 2}, {0, 0})) == "(0,0) (1,1)~ (2,1) (3,2)~ (4,2)");
  CHECK(describe(exact_line_pixels({1, 3}, {0, 0})) == "(0,0) (0,1) (1,2) (1,3)");
  tri::testing::Random random(7);
  for (int trial = 0; trial < 300; ++trial) {
    const glm::ivec2 a = tri::testing::random_point(random, -50, 50);
    const glm::ivec2 b = tri::testing::random_point(random, -50, 50);
    CAPTURE(a.x, a.y, b.x, b.y);
    CHECK(describe(exact_line_pixels(a, b)) == describe(exact_line_pixels(b, a)));
  }
}

TEST_CASE("The exact line handles negative coordinates, ties still rounding up",
          "[01_lines][step1][reference]") {
  // y = -1 - (x + 3) / 2: -1, -1.5, -2, -2.5, -3; "up" is towards +y, so -1.5 becomes -1.
  CHECK(describe(exact_line_pixels({-3, -1}, {1, -3})) ==
        "(-3,-1) (-2,-1)~ (-1,-2) (0,-2)~ (1,-3)");
  CHECK(describe(exact_line_pixels({-1, -5}, {-2, -2})) == "(-1,-5) (-1,-4) (-2,-3) (-2,-2)");
}

TEST_CASE("Each exact pixel is within half a pixel of the true line, exactly half at a tie",
          "[01_lines][step1][reference]") {
  tri::testing::Random random(11);
  for (int trial = 0; trial < 300; ++trial) {
    const glm::ivec2 p0 = tri::testing::random_point(random, -100, 100);
    const glm::ivec2 p1 = tri::testing::random_point(random, -100, 100);
    CAPTURE(p0.x, p0.y, p1.x, p1.y);
    const bool x_major = std::abs(p1.x - p0.x) >= std::abs(p1.y - p0.y);
    const auto major = [&](glm::ivec2 p) -> std::int64_t { return x_major ? p.x : p.y; };
    const auto minor = [&](glm::ivec2 p) -> std::int64_t { return x_major ? p.y : p.x; };
    const glm::ivec2 low = major(p0) <= major(p1) ? p0 : p1;
    const glm::ivec2 high = major(p0) <= major(p1) ? p1 : p0;
    const std::int64_t n = major(high) - major(low);
    const std::vector<ExactLinePixel> pixels = exact_line_pixels(p0, p1);
    REQUIRE(pixels.size() == static_cast<std::size_t>(n) + 1);
    CHECK(pixels.front().pixel == low);
    CHECK(pixels.back().pixel == high);
    for (std::int64_t k = 0; k <= n; ++k) {
      const ExactLinePixel& p = pixels[static_cast<std::size_t>(k)];
      CHECK(major(p.pixel) == major(low) + k);
      // 2n times (pixel minor - true minor); the true minor is minor(low) + dm k / n.
      const std::int64_t offset =
          2 * n * (minor(p.pixel) - minor(low)) - 2 * (minor(high) - minor(low)) * k;
      CHECK(std::abs(offset) <= n);
      CHECK(p.tie == (n > 0 && std::abs(offset) == n));
      if (p.tie) CHECK(offset == n);  // the tie went to the upper of the two pixels
      CHECK(describe(exact_line_pixel_at(p0, p1, major(p.pixel))) == describe(p));
    }
  }
}

TEST_CASE("The exact pixel at one major coordinate is right for endpoints at plus or minus 2^30",
          "[01_lines][step1][reference]") {
  // y = 7 + x / 2^29 from (-2^30, 5) to (2^30, 9).
  const glm::ivec2 a0(-two_30, 5), a1(two_30, 9);
  CHECK(describe(exact_line_pixel_at(a0, a1, -two_30)) == "(-1073741824,5)");
  CHECK(describe(exact_line_pixel_at(a0, a1, two_30)) == "(1073741824,9)");
  CHECK(describe(exact_line_pixel_at(a0, a1, 0)) == "(0,7)");
  CHECK(describe(exact_line_pixel_at(a0, a1, 63)) == "(63,7)");
  CHECK(describe(exact_line_pixel_at(a0, a1, -two_30 + (1 << 28))) == "(-805306368,6)~");
  CHECK(describe(exact_line_pixel_at(a0, a1, -two_30 + (1 << 28) - 1)) == "(-805306369,5)");
  CHECK(describe(exact_line_pixel_at(a1, a0, 0)) == "(0,7)");

  // Steep: x = 3 (y + 2^30) / 2^31 from (0, -2^30) to (3, 2^30).
  const glm::ivec2 b0(0, -two_30), b1(3, two_30);
  CHECK(describe(exact_line_pixel_at(b0, b1, 0)) == "(2,0)~");  // x = 1.5
  CHECK(describe(exact_line_pixel_at(b0, b1, -two_30 + (1 << 29))) == "(1,-536870912)");
  CHECK(describe(exact_line_pixel_at(b0, b1, two_30)) == "(3,1073741824)");

  // y = 2^30 - (2^31 - 1) (x + 2^30) / 2^31 from (-2^30, 2^30) to (2^30, 1 - 2^30): the product
  // 2 (2^31 - 1) k reaches 2^63 near the far end, beyond 64-bit integers.
  const glm::ivec2 c0(-two_30, two_30), c1(two_30, 1 - two_30);
  CHECK(describe(exact_line_pixel_at(c0, c1, 0)) == "(0,1)~");  // y = 0.5
  // At x = 2^30 - 1: y = 2 - 2^30 - 2^-31, nearest 2 - 2^30.
  CHECK(describe(exact_line_pixel_at(c0, c1, two_30 - 1)) == "(1073741823,-1073741822)");
  CHECK(describe(exact_line_pixel_at(c1, c0, two_30 - 1)) == "(1073741823,-1073741822)");
  CHECK(describe(exact_line_pixel_at(c0, c1, -two_30)) == "(-1073741824,1073741824)");
}
