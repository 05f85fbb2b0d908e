#include "chapters/09_anti_aliasing/coverage_error.hpp"

#include <algorithm>
#include <cmath>

#include "chapters/09_anti_aliasing/area_oracle.hpp"

namespace tri::ch09 {
namespace {

void add_triangle(const Triangle& triangle, const PixelCoverageFunction& estimate,
                  AreaDifferences& differences) {
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
      differences.add(estimate(triangle, {x, y}), exact);
    }
  }
}

}  // namespace

bool AreaDifferences::add(double estimate, double exact) noexcept {
  if (estimate == 0 && exact == 0) return false;
  const double difference = std::abs(estimate - exact);
  absolute_ += difference;
  squared_ += difference * difference;
  max_ = std::max(max_, difference);
  ++pixels_;
  return true;
}

CoverageError AreaDifferences::summary() const noexcept {
  if (pixels_ == 0) return {};
  const auto n = static_cast<double>(pixels_);
  return {absolute_ / n, std::sqrt(squared_ / n), max_, pixels_};
}

CoverageError coverage_error(const Triangle& triangle, const PixelCoverageFunction& estimate) {
  AreaDifferences differences;
  add_triangle(triangle, estimate, differences);
  return differences.summary();
}

CoverageError coverage_error(const std::vector<Triangle>& triangles,
                             const PixelCoverageFunction& estimate) {
  AreaDifferences differences;
  for (const auto& t : triangles) add_triangle(t, estimate, differences);
  return differences.summary();
}

}  // namespace tri::ch09
