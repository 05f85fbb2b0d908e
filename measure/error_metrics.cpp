#include "measure/error_metrics.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>
#include <vector>

#include "chapters/07_exact_coverage/algorithms.hpp"
#include "chapters/07_exact_coverage/coverage_oracle.hpp"
#include "common/canvas.hpp"
#include "measure/drawable.hpp"

namespace tri {
namespace {

// The six orders of three vertices; the first is the scene's own.
constexpr std::array<std::array<int, 3>, 6> vertex_orders{
    {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}}};

// The scene's triangles with their vertices taken in the given order.
std::vector<SceneTriangle> reordered_triangles(const Scene& scene,
                                               const std::array<int, 3>& order) {
  std::vector<SceneTriangle> triangles;
  for (const auto& primitive : scene.primitives) {
    const auto* t = std::get_if<SceneTriangle>(&primitive);
    if (t == nullptr) continue;
    triangles.push_back(
        {{t->vertices[order[0]], t->vertices[order[1]], t->vertices[order[2]]}, t->color});
  }
  return triangles;
}

// The draw's counts of the triangles on the scene's canvas, checked to hold one per pixel.
WriteCounts draw_counts(const CountingDraw& draw, const Scene& scene,
                        std::span<const SceneTriangle> triangles) {
  WriteCounts drawn = draw(scene.width, scene.height, triangles);
  const auto pixels =
      static_cast<std::size_t>(scene.width) * static_cast<std::size_t>(scene.height);
  if (drawn.counts.size() != pixels) {
    throw std::logic_error("a counting draw returned " + std::to_string(drawn.counts.size()) +
                           " counts for " + std::to_string(pixels) + " pixels");
  }
  return drawn;
}

}  // namespace

double ErrorReport::error_rate() const noexcept {
  const auto wrong = static_cast<double>(missed + extra);
  if (covered == 0) return wrong == 0 ? 0.0 : wrong;
  return wrong / static_cast<double>(covered);
}

WriteCounts draw_write_counts(const TriangleAlgorithm& algorithm, int width, int height,
                              std::span<const SceneTriangle> triangles) {
  Canvas canvas(width, height);
  canvas.enable_write_counts();
  WriteCounts drawn;
  drawn.rejected = draw_triangles(algorithm, canvas, triangles);
  drawn.counts.assign(canvas.write_counts().begin(), canvas.write_counts().end());
  drawn.outside_writes = canvas.outside_writes();
  return drawn;
}

ErrorReport measure_error(const TriangleAlgorithm& algorithm, const Scene& scene) {
  return measure_error(
      [&algorithm](int width, int height, std::span<const SceneTriangle> triangles) {
        return draw_write_counts(algorithm, width, height, triangles);
      },
      scene);
}

namespace {

// Chapter 07's registered oracle: the truth is the algorithm the report lists, not a copy.
const TriangleAlgorithm& registered_oracle() {
  const TriangleAlgorithm* oracle = algorithm_with_role(ch07::triangle_algorithms(), Role::oracle);
  if (oracle == nullptr) throw std::logic_error("chapter 07 registers no oracle");
  return *oracle;
}

}  // namespace

// [listing measure_error]
ErrorReport measure_error(const CountingDraw& draw, const Scene& scene) {
  const TriangleAlgorithm& oracle = registered_oracle();
  const std::vector<SceneTriangle> own_order = reordered_triangles(scene, vertex_orders[0]);
  const WriteCounts truth = draw_write_counts(oracle, scene.width, scene.height, own_order);
  const WriteCounts drawn = draw_counts(draw, scene, own_order);
  ErrorReport report;
  report.outside_writes = drawn.outside_writes;
  report.rejected = drawn.rejected;
  for (std::size_t i = 0; i < truth.counts.size(); ++i) {
    const std::uint32_t t = truth.counts[i], a = drawn.counts[i];
    report.covered += t;
    report.missed += t > a ? t - a : 0;
    report.extra += a > t ? a - t : 0;
    report.gaps += (t > 0 && a == 0) ? 1 : 0;
    report.overdraw += (a > 1 && a > t) ? 1 : 0;
  }
  std::vector<bool> changed(drawn.counts.size(), false);
  for (std::size_t k = 1; k < vertex_orders.size(); ++k) {
    const WriteCounts other =
        draw_counts(draw, scene, reordered_triangles(scene, vertex_orders[k]));
    report.outside_writes = std::max(report.outside_writes, other.outside_writes);
    for (std::size_t i = 0; i < changed.size(); ++i) {
      if (other.counts[i] != drawn.counts[i]) changed[i] = true;
    }
  }
  report.order_dependent =
      static_cast<std::uint64_t>(std::count(changed.begin(), changed.end(), true));
  return report;
}
// [/listing]

}  // namespace tri
