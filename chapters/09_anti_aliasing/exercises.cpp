// Reference solutions of the chapter's exercises: replace a body with your own.
#include "chapters/09_anti_aliasing/exercises.hpp"

#include <algorithm>
#include <cmath>

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

}  // namespace tri::ch09::exercises
