#include "measure/render_scene.hpp"

#include <chrono>
#include <stdexcept>

#include "chapters/01_lines/lines.hpp"

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

std::vector<SceneTriangle> scene_triangles(const Scene& scene) {
  std::vector<SceneTriangle> triangles;
  for (const auto& primitive : scene.primitives) {
    if (const auto* t = std::get_if<SceneTriangle>(&primitive)) triangles.push_back(*t);
  }
  return triangles;
}

RenderStats render_scene(const Scene& scene, BatchDrawer* drawer, Canvas& canvas,
                         const std::function<void(std::size_t done)>& on_progress) {
  RenderStats stats;
  // Consecutive triangles are drawn as one batch, so a batch algorithm sees them together.
  std::vector<SceneTriangle> run;
  std::size_t done = 0;
  // With progress, pieces grow while they draw quickly and shrink when one takes long, so a report
  // comes about every tenth of a second whether the triangles are tiny or cover the canvas.
  std::size_t piece = 1;
  const auto flush = [&] {
    if (run.empty()) return;
    if (drawer == nullptr) throw std::logic_error("the scene has triangles but no algorithm");
    const auto start = std::chrono::steady_clock::now();
    const std::size_t refused = drawer->draw(canvas, run);
    stats.rejected_triangles += refused;
    stats.triangles += run.size() - refused;
    run.clear();
    if (!on_progress) return;
    const auto took = std::chrono::steady_clock::now() - start;
    if (took < std::chrono::milliseconds(50) && piece < 65536) piece *= 2;
    if (took > std::chrono::milliseconds(200) && piece > 1) piece /= 2;
    on_progress(done);
  };
  for (const auto& primitive : scene.primitives) {
    if (const auto* triangle = std::get_if<SceneTriangle>(&primitive)) {
      run.push_back(*triangle);
      ++done;
      if (on_progress && run.size() >= piece) flush();
    } else {
      flush();
      const auto& line = std::get<SceneLine>(primitive);
      ch01::draw_line_bresenham(canvas, nearest_pixel(line.ends[0]), nearest_pixel(line.ends[1]),
                                line.color);
      ++stats.lines;
      ++done;
      if (on_progress && done % 4096 == 0) on_progress(done);
    }
  }
  flush();
  return stats;
}

RenderStats render_scene(const Scene& scene, const TriangleAlgorithm* algorithm, Canvas& canvas,
                         const std::function<void(std::size_t done)>& on_progress) {
  if (algorithm == nullptr)
    return render_scene(scene, static_cast<BatchDrawer*>(nullptr), canvas, on_progress);
  BatchDrawer drawer(*algorithm);
  return render_scene(scene, &drawer, canvas, on_progress);
}

}  // namespace tri
