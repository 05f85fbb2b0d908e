#include "chapters/09_anti_aliasing/coverage_error.hpp"

#include <algorithm>
#include <cmath>

#include "chapters/09_anti_aliasing/area_oracle.hpp"

namespace tri::ch09 {
namespace {

struct ErrorSums {
  double absolute = 0, squared = 0, max = 0;
  std::size_t pixels = 0;
};

void add_triangle(const Triangle& triangle, const PixelCoverageFunction& estimate, ErrorSums& s) {
  const auto reach = [&](int axis, auto pick) {
    return pick({triangle[0][axis], triangle[1][axis], triangle[2][axis]});
  };
  const auto lowest = [](std::initializer_list<double> v) { return std::min(v); };
  const auto highest = [](std::initializer_list<double> v) { return std::max(v); };
  for (int y = static_cast<int>(std::floor(reach(1, lowest))) - 1;
       y <= static_cast<int>(std::ceil(reach(1, highest))) + 1; ++y) {
    for (int x = static_cast<int>(std::floor(reach(0, lowest))) - 1;
         x <= static_cast<int>(std::ceil(reach(0, highest))) + 1; ++x) {
      const double exact = exact_coverage(triangle, {x, y}).to_double();
      const double estimated = estimate(triangle, {x, y});
      if (exact == 0 && estimated == 0) continue;
      const double difference = std::abs(estimated - exact);
      s.absolute += difference;
      s.squared += difference * difference;
      s.max = std::max(s.max, difference);
      ++s.pixels;
    }
  }
}

CoverageError summary(const ErrorSums& s) {
  if (s.pixels == 0) return {};
  const auto n = static_cast<double>(s.pixels);
  return {s.absolute / n, std::sqrt(s.squared / n), s.max, s.pixels};
}

}  // namespace

CoverageError coverage_error(const Triangle& triangle, const PixelCoverageFunction& estimate) {
  ErrorSums sums;
  add_triangle(triangle, estimate, sums);
  return summary(sums);
}

CoverageError coverage_error(const std::vector<Triangle>& triangles,
                             const PixelCoverageFunction& estimate) {
  ErrorSums sums;
  for (const auto& t : triangles) add_triangle(t, estimate, sums);
  return summary(sums);
}

}  // namespace tri::ch09
