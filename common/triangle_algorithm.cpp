#include "triangle_algorithm.hpp"

#include <cmath>

#include "scene.hpp"

namespace tri {

std::string_view rule_name(CoverageRule rule) noexcept {
  switch (rule) {
    case CoverageRule::top_left:
      return "top-left";
    case CoverageRule::inclusive:
      return "inclusive";
    case CoverageRule::approximate:
      return "approximate";
  }
  return "approximate";
}

std::string_view describe(DrawResult result) noexcept {
  switch (result) {
    case DrawResult::drawn:
      return "drawn";
    case DrawResult::rejected_non_finite:
      return "not drawn: a vertex coordinate is NaN or infinite";
    case DrawResult::rejected_out_of_range:
      return "not drawn: a vertex coordinate is outside ±2^30";
  }
  return "not drawn";
}

DrawResult validate_triangle(const Triangle& triangle) noexcept {
  for (const glm::dvec2& v : triangle) {
    if (!std::isfinite(v.x) || !std::isfinite(v.y)) return DrawResult::rejected_non_finite;
  }
  for (const glm::dvec2& v : triangle) {
    if (std::abs(v.x) > max_scene_coordinate || std::abs(v.y) > max_scene_coordinate) {
      return DrawResult::rejected_out_of_range;
    }
  }
  return DrawResult::drawn;
}

DrawResult draw_triangle(const TriangleAlgorithm& algorithm, Canvas& canvas,
                         const Triangle& triangle, Color color) {
  const DrawResult result = validate_triangle(triangle);
  if (result == DrawResult::drawn) algorithm.draw(canvas, triangle, color);
  return result;
}

glm::ivec2 nearest_pixel(glm::dvec2 p) noexcept {
  return {static_cast<int>(std::floor(p.x + 0.5)), static_cast<int>(std::floor(p.y + 0.5))};
}

}  // namespace tri
