// Step 1 of the chapter: Gambetta's interpolate(), the helper his lines and triangles share.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "chapters/01_lines/interpolate.hpp"
#include "tests/support/pixels.hpp"

using tri::ch01::interpolate;

TEST_CASE("interpolate returns one value per integer from i0 to i1, both ends included",
          "[01_lines][step2][interpolate]") {
  // Every value here is a multiple of 0.5, so the running sum is exact and == is fair.
  CHECK(interpolate(0, 0.0, 4, 2.0) == std::vector<double>{0.0, 0.5, 1.0, 1.5, 2.0});
  CHECK(interpolate(-2, 1.0, 2, 3.0) == std::vector<double>{1.0, 1.5, 2.0, 2.5, 3.0});
  CHECK(interpolate(10, 7.0, 11, 8.0) == std::vector<double>{7.0, 8.0});
  // The C++ port's `i < i1` loop would have returned 4 values for the first call, not 5.
  CHECK(interpolate(0, 0.0, 4, 2.0).size() == 5);
}

TEST_CASE("interpolate with i0 == i1 returns the single value d0, whatever d1 is",
          "[01_lines][step2][interpolate]") {
  CHECK(interpolate(3, 7.5, 3, -2.0) == std::vector<double>{7.5});
  CHECK(interpolate(-5, 0.0, -5, 0.0) == std::vector<double>{0.0});
}

TEST_CASE("interpolate follows a decreasing function down to d1",
          "[01_lines][step2][interpolate]") {
  CHECK(interpolate(0, 10.0, 5, 0.0) == std::vector<double>{10.0, 8.0, 6.0, 4.0, 2.0, 0.0});
  CHECK(interpolate(-1, 1.0, 3, -1.0) == std::vector<double>{1.0, 0.5, 0.0, -0.5, -1.0});
}

TEST_CASE("interpolate starts at d0 and ends at d1 on seeded random inputs",
          "[01_lines][step2][interpolate]") {
  tri::testing::Random random(101);
  for (int trial = 0; trial < 500; ++trial) {
    const int i0 = random.integer(-1000, 1000);
    const int i1 = i0 + random.integer(0, 2000);
    const double d0 = random.real(-1000.0, 1000.0);
    const double d1 = random.real(-1000.0, 1000.0);
    CAPTURE(i0, i1, d0, d1);
    const std::vector<double> values = interpolate(i0, d0, i1, d1);
    REQUIRE(values.size() == static_cast<std::size_t>(i1 - i0) + 1);
    CHECK(values.front() == d0);
    CHECK(std::abs(values.back() - d1) <= 1e-9);
    // Every sample, not only the last, stays on the line d0 + (d1 - d0) (i - i0) / (i1 - i0).
    const double slope = i1 == i0 ? 0.0 : (d1 - d0) / (i1 - i0);
    double worst = 0.0;
    for (std::size_t k = 0; k < values.size(); ++k) {
      worst = std::max(worst, std::abs(values[k] - (d0 + slope * static_cast<double>(k))));
    }
    CHECK(worst <= 1e-9);
  }
}
