// The one file an algorithm needs: its function and its entry in its chapter's registration.
// Here the "chapter" is this test target, which registers the algorithm the way chapters do.
#include <algorithm>
#include <array>
#include <cmath>
#include <span>

#include "common/triangle_algorithm.hpp"

namespace tri::one_file {
namespace {

// Twice the signed area of (a, b, p): positive when p is left of a->b.
double edge(glm::dvec2 a, glm::dvec2 b, glm::dvec2 p) {
  return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

// Every pixel centre of the bounding box (clipped to the canvas) whose three edge values, in
// double, share the triangle's winding; centres on an edge count as inside.
void draw_centres_in_box(Canvas& canvas, const Triangle& t, Color color) {
  const double area = edge(t[0], t[1], t[2]);
  if (area == 0) return;
  const double sign = area > 0 ? 1.0 : -1.0;
  const auto lowest = [](double a, double b, double c) { return std::min({a, b, c}); };
  const auto highest = [](double a, double b, double c) { return std::max({a, b, c}); };
  const int x0 = std::max(0, static_cast<int>(std::ceil(lowest(t[0].x, t[1].x, t[2].x))));
  const int y0 = std::max(0, static_cast<int>(std::ceil(lowest(t[0].y, t[1].y, t[2].y))));
  const int x1 =
      std::min(canvas.width() - 1, static_cast<int>(std::floor(highest(t[0].x, t[1].x, t[2].x))));
  const int y1 =
      std::min(canvas.height() - 1, static_cast<int>(std::floor(highest(t[0].y, t[1].y, t[2].y))));
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const glm::dvec2 p(x, y);
      if (sign * edge(t[0], t[1], p) >= 0 && sign * edge(t[1], t[2], p) >= 0 &&
          sign * edge(t[2], t[0], p) >= 0) {
        canvas.put_pixel(x, y, color);
      }
    }
  }
}

}  // namespace

std::span<const TriangleAlgorithm> triangle_algorithms() {
  static constexpr auto algorithms = std::to_array<TriangleAlgorithm>({
      {.name = "one_file_centres_in_box",
       .chapter = "one_file_algorithm",
       .rule = CoverageRule::approximate,
       .summary = "every pixel centre of the bounding box tested with edge functions in double",
       .draw = draw_centres_in_box},
  });
  return algorithms;
}

}  // namespace tri::one_file
