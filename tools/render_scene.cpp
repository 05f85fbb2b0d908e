#include "render_scene.hpp"

#include <stdexcept>

#include "lines.hpp"

namespace tri {

Canvas make_canvas(const Scene& scene) {
  return Canvas(scene.width, scene.height, scene.background);
}

std::size_t count_triangles(const Scene& scene) {
  std::size_t n = 0;
  for (const auto& primitive : scene.primitives)
    n += std::holds_alternative<SceneTriangle>(primitive);
  return n;
}

RenderStats render_scene(const Scene& scene, const TriangleAlgorithm* algorithm, Canvas& canvas) {
  RenderStats stats;
  for (const auto& primitive : scene.primitives) {
    if (const auto* triangle = std::get_if<SceneTriangle>(&primitive)) {
      if (algorithm == nullptr) throw std::logic_error("the scene has triangles but no algorithm");
      const DrawResult result =
          draw_triangle(*algorithm, canvas, triangle->vertices, triangle->color);
      if (result == DrawResult::drawn) {
        ++stats.triangles;
      } else {
        ++stats.rejected_triangles;
      }
    } else {
      const auto& line = std::get<SceneLine>(primitive);
      ch01::draw_line_bresenham(canvas, nearest_pixel(line.ends[0]), nearest_pixel(line.ends[1]),
                                line.color);
      ++stats.lines;
    }
  }
  return stats;
}

}  // namespace tri
