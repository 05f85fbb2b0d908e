#include "measure/peers/y_down_peer.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tri {

PixelWindow pixels_around(const SceneTriangle& triangle, int width, int height) noexcept {
  double x_min = triangle.vertices[0].x, x_max = x_min;
  double y_min = triangle.vertices[0].y, y_max = y_min;
  for (const glm::dvec2 v : triangle.vertices) {
    x_min = std::min(x_min, v.x), x_max = std::max(x_max, v.x);
    y_min = std::min(y_min, v.y), y_max = std::max(y_max, v.y);
  }
  // Clamp in double first: a vertex far off the canvas must not overflow the int conversion.
  const auto clamp_to = [](double v, int limit) {
    return static_cast<int>(std::clamp(v, -1.0, static_cast<double>(limit)));
  };
  PixelWindow window;
  window.x_begin = std::max(0, clamp_to(std::floor(x_min) - 1, width));
  window.x_end = std::min(width, clamp_to(std::ceil(x_max) + 2, width));
  window.y_begin = std::max(0, clamp_to(std::floor(y_min) - 1, height));
  window.y_end = std::min(height, clamp_to(std::ceil(y_max) + 2, height));
  return window;
}

void require_within(std::span<const SceneTriangle> triangles, int height, double limit,
                    const std::string& peer) {
  for (const SceneTriangle& triangle : triangles) {
    for (const glm::dvec2 v : triangle.vertices) {
      const glm::dvec2 p = to_y_down(v, height);
      if (!(std::abs(p.x) <= limit && std::abs(p.y) <= limit)) {
        throw std::runtime_error(peer + " cannot draw this scene: a vertex maps to (" +
                                 std::to_string(p.x) + ", " + std::to_string(p.y) +
                                 "), beyond its coordinate range of +-" + std::to_string(limit));
      }
    }
  }
}

}  // namespace tri
