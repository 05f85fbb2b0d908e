#include <limits>
#include <vector>

#include <catch2/catch.hpp>

#include "common/random.hpp"
#include "measure/plot/log_axis.hpp"

using tri::DecadeRange;
using tri::ErrorAxis;
using tri::LogScale;

TEST_CASE("A log scale puts each decade an equal distance apart", "[measure][log_axis]") {
  const LogScale scale{-3, 1, 100, 500};  // four decades over 400 px
  CHECK(scale.position(1e-3) == Approx(100));
  CHECK(scale.position(1e-2) == Approx(200));
  CHECK(scale.position(1.0) == Approx(400));
  CHECK(scale.position(10.0) == Approx(500));
  CHECK(scale.position(std::sqrt(10.0)) == Approx(450));
}

TEST_CASE("A log scale is monotonic, growing either way", "[measure][log_axis]") {
  const LogScale across{-6, 2, 90, 720};
  const LogScale upward{0, 4, 560, 80};  // SVG y: larger values higher up, smaller y
  tri::Random random(909);
  std::vector<double> values;
  for (int i = 0; i < 500; ++i) values.push_back(std::pow(10.0, random.real(-8, 4)));
  std::sort(values.begin(), values.end());
  for (std::size_t i = 1; i < values.size(); ++i) {
    CHECK(across.position(values[i - 1]) <= across.position(values[i]));
    CHECK(upward.position(values[i - 1]) >= upward.position(values[i]));
  }
}

TEST_CASE("Values beyond the decades, zero and negatives are clamped to the ends",
          "[measure][log_axis]") {
  const LogScale scale{-2, 2, 0, 400};
  CHECK(scale.position(1e-9) == 0);
  CHECK(scale.position(0.0) == 0);
  CHECK(scale.position(-1.0) == 0);
  CHECK(scale.position(1e9) == 400);
  CHECK(scale.position(std::numeric_limits<double>::infinity()) == 400);
}

TEST_CASE("An error of 0 is drawn at the floor, left of every positive error",
          "[measure][log_axis]") {
  const ErrorAxis axis{{-6, -1, 160, 720}, 125};
  CHECK(axis.position(0.0) == 125);
  for (const double rate : {1e-12, 1e-6, 1e-3, 0.5, 10.0}) {
    CHECK(axis.position(rate) >= 160);
    CHECK(axis.position(rate) > axis.position(0.0));
  }
}

TEST_CASE("The decades covering a set of values are rounded outward to whole decades",
          "[measure][log_axis]") {
  const auto covering = [](std::vector<double> values) {
    const DecadeRange d = tri::decades_covering(values);
    return std::make_pair(d.low, d.high);
  };
  CHECK(covering({0.003, 42.0}) == std::make_pair(-3, 2));
  CHECK(covering({0.0, -4.0, 0.05}) == std::make_pair(-2, -1));
  CHECK(covering({10.0}) == std::make_pair(1, 2));
  CHECK(covering({5.0, 5.0}) == std::make_pair(0, 1));
  CHECK(covering({}) == std::make_pair(0, 1));
  CHECK(covering({std::numeric_limits<double>::infinity(), 100.0, 999.0}) == std::make_pair(2, 3));
}
