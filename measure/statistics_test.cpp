#include <stdexcept>
#include <vector>

#include <catch2/catch.hpp>

#include "measure/statistics.hpp"

using tri::geometric_mean;
using tri::Spread;
using tri::spread_of;

// One slow sample (another process took the core) moves the mean, not the median.
TEST_CASE("The median of an odd number of samples is the middle one", "[measure][statistics]") {
  const Spread s = spread_of({0.3, 0.1, 5.0, 0.2, 0.4});
  CHECK(s.median == 0.3);
  CHECK(s.min == 0.1);
  CHECK(s.max == 5.0);
}

TEST_CASE("The median of an even number of samples is the mean of the two middle ones",
          "[measure][statistics]") {
  const Spread s = spread_of({100.0, 1.0, 3.0, 2.0});
  CHECK(s.median == 2.5);
  CHECK(s.min == 1.0);
  CHECK(s.max == 100.0);
}

TEST_CASE("One sample is its own median, minimum and maximum", "[measure][statistics]") {
  const Spread s = spread_of({7.0});
  CHECK(s.median == 7.0);
  CHECK(s.min == 7.0);
  CHECK(s.max == 7.0);
}

TEST_CASE("The spread of no samples is refused", "[measure][statistics]") {
  CHECK_THROWS_AS(spread_of({}), std::invalid_argument);
}

TEST_CASE("The geometric mean skips values that are not positive", "[measure][statistics]") {
  const std::vector<double> values{1.0, 100.0, 0.0, -5.0};
  CHECK(geometric_mean(values) == Approx(10.0));
  const std::vector<double> cube{2.0, 4.0, 8.0};
  CHECK(geometric_mean(cube) == Approx(4.0));
  const std::vector<double> none{0.0, -1.0};
  CHECK(geometric_mean(none) == 0.0);
}
