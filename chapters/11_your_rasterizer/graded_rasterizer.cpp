#include "chapters/11_your_rasterizer/graded_rasterizer.hpp"

#include <utility>
#include <variant>

namespace tri::conformance {
namespace {

std::vector<SceneTriangle> triangles_of(const Scene& scene) {
  std::vector<SceneTriangle> triangles;
  for (const auto& primitive : scene.primitives) {
    if (const auto* t = std::get_if<SceneTriangle>(&primitive)) triangles.push_back(*t);
  }
  return triangles;
}

Answer counts_of(const Canvas& canvas) {
  const auto counts = canvas.write_counts();
  return {.kind = Answer::Kind::counts, .counts = {counts.begin(), counts.end()}, .reason = {}};
}

Canvas counting_canvas(const Scene& scene) {
  Canvas canvas(scene.width, scene.height, scene.background);
  canvas.enable_write_counts();
  return canvas;
}

}  // namespace

GradedRasterizer graded_algorithm(const TriangleAlgorithm& algorithm) {
  return {.name = std::string(algorithm.name),
          .threaded = algorithm.threaded,
          .draw = [&algorithm](const Scene& scene, Threads threads, Deadline) {
            Canvas canvas = counting_canvas(scene);
            const auto triangles = triangles_of(scene);
            if (threads == Threads::all) {
              draw_triangles(algorithm, canvas, triangles);
            } else {
              for (const auto& t : triangles) draw_triangle(algorithm, canvas, t.vertices, t.color);
            }
            return counts_of(canvas);
          }};
}

GradedRasterizer graded_fill(std::string name, FillFunction fill) {
  return {.name = std::move(name),
          .threaded = false,
          .draw = [fill = std::move(fill)](const Scene& scene, Threads, Deadline) {
            Canvas canvas = counting_canvas(scene);
            for (const auto& t : triangles_of(scene)) {
              if (validate_triangle(t.vertices) == DrawResult::drawn)
                fill(canvas, t.vertices, t.color);
            }
            return counts_of(canvas);
          }};
}

}  // namespace tri::conformance
