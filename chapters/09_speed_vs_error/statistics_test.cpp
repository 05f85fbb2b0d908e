#include <stdexcept>
#include <vector>

#include <catch2/catch.hpp>

#include "chapters/09_speed_vs_error/statistics.hpp"

using tri::ch09::geometric_mean;
using tri::ch09::Spread;
using tri::ch09::spread_of;

// One slow sample (another process took the core) moves the mean, not the median.
TEST_CASE("The median of an odd number of samples is the middle one", "[statistics]") {
  const Spread s = spread_of({0.3, 0.1, 5.0, 0.2, 0.4});
  CHECK(s.median == 0.3);
  CHECK(s.min == 0.1);
  CHECK(s.max == 5.0);
}

TEST_CASE("The median of an even number of samples is the mean of the two middle ones",
          "[statistics]") {
  const Spread s = spread_of({100.0, 1.0, 3.0, 2.0});
  CHECK(s.median == 2.5);
  CHECK(s.min == 1.0);
  CHECK(s.max == 100.0);
}

TEST_CASE("One sample is its own median, minimum and maximum", "[statistics]") {
  const Spread s = spread_of({7.0});
  CHECK(s.median == 7.0);
  CHECK(s.min == 7.0);
  CHECK(s.max == 7.0);
}

TEST_CASE("The spread of no samples is refused", "[statistics]") {
  CHECK_THROWS_AS(spread_of({}), std::invalid_argument);
}

TEST_CASE("The geometric mean skips values that are not positive", "[statistics]") {
  const std::vector<double> values{1.0, 100.0, 0.0, -5.0};
  CHECK(geometric_mean(values) == Approx(10.0));
  const std::vector<double> cube{2.0, 4.0, 8.0};
  CHECK(geometric_mean(cube) == Approx(4.0));
  const std::vector<double> none{0.0, -1.0};
  CHECK(geometric_mean(none) == 0.0);
}
