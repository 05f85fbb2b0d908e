#include "common/triangle_algorithm.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/enum_names.hpp"
#include "common/scene.hpp"

namespace tri {

const TriangleAlgorithm* algorithm_with_role(std::span<const TriangleAlgorithm> algorithms,
                                             Role role) noexcept {
  for (const TriangleAlgorithm& a : algorithms) {
    if (a.role == role) return &a;
  }
  return nullptr;
}

namespace {

constexpr auto result_texts = all_names<DrawResult::rejected_out_of_range>(
    {{DrawResult::drawn, "drawn"},
     {DrawResult::rejected_non_finite, "not drawn: a vertex coordinate is NaN or infinite"},
     {DrawResult::rejected_out_of_range, "not drawn: a vertex coordinate is outside ±2^30"}});

}  // namespace

std::string_view describe(DrawResult result) noexcept {
  return name_in(result_texts, result, "not drawn");
}

DrawResult validate_triangle(const Triangle& triangle) noexcept {
  // The usual case in one test without branches (|c| <= limit is false for NaN and infinities
  // too): checking 100,000 triangles this way took about a third less time than the loops below.
  int within = 1;
  for (const glm::dvec2& v : triangle) {
    within &=
        int{std::abs(v.x) <= max_scene_coordinate} & int{std::abs(v.y) <= max_scene_coordinate};
  }
  if (within != 0) return DrawResult::drawn;
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

namespace {

// Not floor(x + 0.5): for x = 0.49999999999999994 the sum itself rounds up to 1. x - floor(x) is
// exact (Sterbenz) except for -0.5 < x < 0, where it exceeds a half either way.
int nearest_integer(double x) noexcept {
  const double below = std::floor(x);
  return static_cast<int>(x - below >= 0.5 ? below + 1.0 : below);
}

}  // namespace

BatchDrawer::BatchDrawer(const TriangleAlgorithm& algorithm)
    : algorithm_(&algorithm),
      renderer_(algorithm.make_renderer != nullptr ? algorithm.make_renderer() : nullptr) {}

PreparedBatch::PreparedBatch(std::span<const SceneTriangle> triangles) {
  reserve(triangles.size());
  for (const SceneTriangle& t : triangles) add(t);
}

PreparedBatch::PreparedBatch(std::span<const SceneTriangle> triangles, CanvasExtent canvas)
    : PreparedBatch(canvas) {
  // Room for all, as prepare_drawing reserves a run: the pages of culled ones are never touched.
  reserve(triangles.size());
  for (const SceneTriangle& t : triangles) add(t);
}

namespace {

// Whether the triangle's bounding box comes within cull_margin_pixels of the canvas's pixel
// centres 0..width-1 and 0..height-1. Precondition: its coordinates are finite. Without branches
// (min, max and & instead of &&): which triangles lie outside is unpredictable.
bool meets_canvas(const Triangle& t, CanvasExtent canvas) noexcept {
  const double low_x = std::min(std::min(t[0].x, t[1].x), t[2].x);
  const double high_x = std::max(std::max(t[0].x, t[1].x), t[2].x);
  const double low_y = std::min(std::min(t[0].y, t[1].y), t[2].y);
  const double high_y = std::max(std::max(t[0].y, t[1].y), t[2].y);
  return (high_x >= -cull_margin_pixels) & (low_x <= canvas.width - 1 + cull_margin_pixels) &
         (high_y >= -cull_margin_pixels) & (low_y <= canvas.height - 1 + cull_margin_pixels);
}

}  // namespace

DrawResult PreparedBatch::add(const SceneTriangle& triangle) {
  const DrawResult result = validate_triangle(triangle.vertices);
  if (result != DrawResult::drawn) {
    ++refused_;
  } else if (cull_to_ && !meets_canvas(triangle.vertices, *cull_to_)) {
    ++culled_;
  } else {
    accepted_.push_back(triangle);
  }
  return result;
}

bool PreparedBatch::fits(const Canvas& canvas) const noexcept {
  return !cull_to_ || (canvas.width() <= cull_to_->width && canvas.height() <= cull_to_->height);
}

void BatchDrawer::draw_accepted(Canvas& canvas, std::span<const SceneTriangle> accepted) {
  if (renderer_ != nullptr) {
    renderer_->draw(canvas, accepted);
  } else if (algorithm_->draw_batch != nullptr) {
    algorithm_->draw_batch(canvas, accepted);
  } else {
    for (const SceneTriangle& t : accepted) algorithm_->draw(canvas, t.vertices, t.color);
  }
}

std::size_t BatchDrawer::draw(Canvas& canvas, std::span<const SceneTriangle> triangles) {
  std::size_t refused = 0;
  for (const SceneTriangle& t : triangles)
    refused += validate_triangle(t.vertices) != DrawResult::drawn;
  if (refused == 0) {
    draw_accepted(canvas, triangles);
    return 0;
  }
  valid_.clear();  // only when some input was refused
  for (const SceneTriangle& t : triangles) {
    if (validate_triangle(t.vertices) == DrawResult::drawn) valid_.push_back(t);
  }
  draw_accepted(canvas, valid_);
  return refused;
}

std::size_t BatchDrawer::draw(Canvas& canvas, const PreparedBatch& batch) {
  if (!batch.fits(canvas))
    throw std::invalid_argument("a culled batch drawn on a canvas larger than it was culled for");
  draw_accepted(canvas, batch.triangles());
  return batch.refused();
}

std::size_t draw_triangles(const TriangleAlgorithm& algorithm, Canvas& canvas,
                           std::span<const SceneTriangle> triangles) {
  return BatchDrawer(algorithm).draw(canvas, triangles);
}

glm::ivec2 nearest_pixel(glm::dvec2 p) noexcept {
  return {nearest_integer(p.x), nearest_integer(p.y)};
}

}  // namespace tri
