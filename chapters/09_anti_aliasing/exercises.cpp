// Reference solutions of the chapter's exercises: replace a body with your own.
#include "chapters/09_anti_aliasing/exercises.hpp"

#include <algorithm>
#include <cmath>

#include "chapters/09_anti_aliasing/area_oracle.hpp"

namespace tri::ch09::exercises {

double composite_over(std::span<const double> coverages) {
  double v = 0;
  for (const double c : coverages) v += c * (1 - v);
  return v;
}

double srgb_encode(double linear) {
  return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1 / 2.4) - 0.055;
}

double tent_filtered_edge(double d) {
  // The tent's weight left of x = d: 0 before -1, two parabolas meeting at 1/2, 1 after 1.
  const double t = std::clamp(d, -1.0, 1.0);
  return t <= 0 ? (1 + t) * (1 + t) / 2 : 1 - (1 - t) * (1 - t) / 2;
}

double fill_rule_coverage(std::span<const Triangle> shapes, glm::ivec2 pixel,
                          const SamplePattern& pattern, FillRule rule) {
  int inside = 0;
  for (const glm::ivec2 offset : pattern.offsets) {
    const SamplePattern one{"one sample", {offset}};
    int winding = 0;
    for (const Triangle& t : shapes) {
      if (sampled_coverage(t, pixel, one) == 0) continue;
      const glm::dvec2 ab = t[1] - t[0], ac = t[2] - t[0];
      winding += ab.x * ac.y - ab.y * ac.x > 0 ? 1 : -1;
    }
    inside += rule == FillRule::non_zero ? winding != 0 : winding % 2 != 0;
  }
  return static_cast<double>(inside) / static_cast<double>(pattern.offsets.size());
}

std::vector<Fraction> accumulated_row(const Triangle& triangle, int row, int width) {
  std::vector<Fraction> buffer(static_cast<std::size_t>(width) + 1, Fraction(0));
  for (std::size_t k = 0; k < 3; ++k) {
    for (int x = 0; x < width; ++x) {
      const EdgeInPixelRow parts = edge_in_pixel_row(triangle[k], triangle[(k + 1) % 3], {x, row});
      const auto at = static_cast<std::size_t>(x);
      buffer[at] = buffer[at] + parts.area();
      buffer[at + 1] = buffer[at + 1] + (parts.inside_height - parts.area());
    }
  }
  std::vector<Fraction> coverages;
  Fraction running = 0;
  for (int x = 0; x < width; ++x) {
    running = running + buffer[static_cast<std::size_t>(x)];
    coverages.push_back(Fraction(0) - running);
  }
  return coverages;
}

}  // namespace tri::ch09::exercises
