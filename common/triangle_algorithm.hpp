/// @file
/// The one entry point every triangle algorithm of the book is called through, and what the
/// registry records about each (@ref design_registry "docs/DESIGN.md section 5").
#pragma once

#include <array>
#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>

#include "common/canvas.hpp"
#include "common/color.hpp"
#include "common/drawable.hpp"
#include "common/large_buffer.hpp"
#include "common/scene.hpp"

namespace tri {

/// Three vertices in canvas pixel units (integer values are pixel centres).
using Triangle = std::array<glm::dvec2, 3>;

/// Draws one triangle in one colour. Called only with finite vertices within the scene limits.
using DrawTriangleFunction = void (*)(Canvas& canvas, const Triangle& triangle, Color color);

/// Draws only the pixels of rows first_row..last_row (0 <= first_row <= last_row < height) that
/// DrawTriangleFunction writes there: drawing every band of a partition of the canvas's rows in
/// turn writes the same pixels, as often. Lets a caller split one huge triangle's work into bands.
using DrawTriangleRowsFunction = void (*)(Canvas& canvas, const Triangle& triangle, Color color,
                                          int first_row, int last_row);

/// Draws many triangles as if one after the other (later ones paint over earlier ones), for
/// algorithms that work on a whole batch at once, e.g. by splitting the canvas among threads.
/// Called only with triangles that passed validate_triangle.
using DrawBatchFunction = void (*)(Canvas& canvas, std::span<const SceneTriangle> triangles);

/// What an algorithm keeps from one batch to the next, e.g. threads started once and kept, the
/// way a real renderer keeps its workers across frames. Made before a run of batches (outside
/// any timed region), used for each, destroyed after the last.
class BatchRenderer {
 public:
  virtual ~BatchRenderer() = default;
  /// Draws many triangles as if one after the other, on a canvas of any size. Called only with
  /// triangles that passed validate_triangle, one batch at a time.
  virtual void draw(Canvas& canvas, std::span<const SceneTriangle> triangles) = 0;
};

/// Makes an algorithm's BatchRenderer.
using MakeRendererFunction = std::unique_ptr<BatchRenderer> (*)();

/// One of chapter 08's narrow canvases (step 8: index8 or mask1) with what to write into it;
/// defined there, where it is drawn.
struct NarrowTarget;

/// Draws many triangles into a narrow target as if one after the other. Called only with
/// triangles that passed validate_triangle.
using DrawNarrowFunction = void (*)(NarrowTarget& target, std::span<const SceneTriangle> triangles);

/// A registered triangle algorithm.
struct TriangleAlgorithm {
  std::string_view name;     ///< stable name, e.g. "scanline_single_loop"
  std::string_view chapter;  ///< chapter folder, e.g. "04_scanline"
  CoverageRule rule;
  std::string_view summary;  ///< one line for `raster --list`
  DrawTriangleFunction draw;
  bool threaded = false;                   ///< uses more than one thread
  DrawBatchFunction draw_batch = nullptr;  ///< optional: a faster way to draw many at once
  /// Optional, instead of draw_batch: the same with state kept between batches (BatchDrawer).
  MakeRendererFunction make_renderer = nullptr;
  /// Algorithms that differ only in numeric precision share a family ("fixed_point",
  /// "barycentric"); empty for the others. The report joins a family's points into a line.
  std::string_view precision_family = {};
  int precision_bits = 0;  ///< fractional bits of a fixed point, or significand bits of a float
  /// Optional: draw restricted to a band of rows (`raster` reports progress inside a huge
  /// triangle).
  DrawTriangleRowsFunction draw_rows = nullptr;
  Outputs outputs = colour_outputs;  ///< what it writes (narrow_outputs: chapter 08's step 8 too)
  /// With narrow_outputs: how it draws the narrow canvases.
  DrawNarrowFunction draw_narrow = nullptr;
  Role role = Role::none;  ///< a part a measuring program gives it, if any
};

/// The algorithm whose registration declares this role, or nullptr.
const TriangleAlgorithm* algorithm_with_role(std::span<const TriangleAlgorithm> algorithms,
                                             Role role) noexcept;

/// Whether a triangle was drawn or refused before reaching the algorithm.
enum class DrawResult {
  drawn,
  rejected_non_finite,   ///< a coordinate was NaN or infinite
  rejected_out_of_range  ///< a coordinate was beyond ±2^30
};

/// One line describing a result, for messages.
std::string_view describe(DrawResult result) noexcept;

/// Checks that every coordinate is finite and within the scene limits.
DrawResult validate_triangle(const Triangle& triangle) noexcept;

/// The library entry point: validates the triangle, then lets the algorithm draw it. A refused
/// triangle draws nothing and the result says why.
DrawResult draw_triangle(const TriangleAlgorithm& algorithm, Canvas& canvas,
                         const Triangle& triangle, Color color);

/// The size of the canvases a culled PreparedBatch may be drawn on: this one or a smaller one.
struct CanvasExtent {
  int width = 0;
  int height = 0;
};

/// How far outside a canvas, in pixels, a triangle's bounding box may lie and still be kept by a
/// culled batch: rounding a vertex to its nearest pixel centre moves it half a pixel.
inline constexpr double cull_margin_pixels = 1.0;

/// Triangles checked once: those that passed validate_triangle, in order, in the layout every
/// batch entry point takes, and how many were refused. A BatchDrawer draws it without checking
/// or copying anything again, so a program that draws the same triangles every frame prepares
/// them once, before its clock runs. A batch made for a canvas also leaves out (culls) the
/// triangles whose bounding box lies more than cull_margin_pixels outside it, which can write no
/// pixel of it; it is drawn only on that canvas or a smaller one.
class PreparedBatch {
 public:
  PreparedBatch() = default;
  explicit PreparedBatch(std::span<const SceneTriangle> triangles);
  /// An empty batch that culls to `canvas`.
  explicit PreparedBatch(CanvasExtent canvas) : cull_to_(canvas) {}
  /// The triangles' batch, culled to `canvas`.
  PreparedBatch(std::span<const SceneTriangle> triangles, CanvasExtent canvas);

  /// Makes room for `count` more triangles, so adding them allocates once.
  void reserve(std::size_t count) { accepted_.reserve(accepted_.size() + count); }
  /// Checks one more triangle and keeps it when it passes and is not culled; says what the check
  /// found (a culled triangle passed it: drawn, drawing nothing).
  DrawResult add(const SceneTriangle& triangle);
  /// The kept triangles, in the order they were added.
  std::span<const SceneTriangle> triangles() const noexcept { return accepted_; }
  /// How many were refused (non-finite or out of range).
  std::size_t refused() const noexcept { return refused_; }
  /// How many passed the check but were left out, lying wholly outside the canvas.
  std::size_t culled() const noexcept { return culled_; }
  /// Whether it may be drawn on the canvas: always, unless it culls to a smaller one.
  bool fits(const Canvas& canvas) const noexcept;

 private:
  // Filled once, drawn every frame: huge pages make its page faults few
  // (docs/performance_notes.md).
  std::vector<SceneTriangle, LargeBufferAllocator<SceneTriangle>> accepted_;
  std::size_t refused_ = 0;
  std::size_t culled_ = 0;
  std::optional<CanvasExtent> cull_to_;  // none: keeps every triangle that passes the check
};

/// Draws batches of triangles with one algorithm; every caller that draws batches goes through
/// one. Each triangle is validated, refused ones are skipped, and the rest go to the algorithm's
/// renderer (made once, by the constructor, and kept until the drawer goes), else to its batch
/// entry point, else one by one. Make one before a run of frames and draw every frame with it,
/// so that no frame pays for what the renderer keeps (starting its threads).
class BatchDrawer {
 public:
  explicit BatchDrawer(const TriangleAlgorithm& algorithm);

  /// Draws the triangles in order; returns how many were refused. One batch at a time.
  std::size_t draw(Canvas& canvas, std::span<const SceneTriangle> triangles);
  /// Draws a prepared batch's triangles in order, checking none again; returns how many its
  /// preparation refused. What a program that draws the same triangles every frame times. Throws
  /// std::invalid_argument for a culled batch and a canvas larger than the one it culls to.
  std::size_t draw(Canvas& canvas, const PreparedBatch& batch);
  /// The algorithm it draws with.
  const TriangleAlgorithm& algorithm() const noexcept { return *algorithm_; }

 private:
  // Hands triangles that passed validate_triangle to the renderer, the batch entry or draw.
  void draw_accepted(Canvas& canvas, std::span<const SceneTriangle> accepted);

  const TriangleAlgorithm* algorithm_;
  std::unique_ptr<BatchRenderer> renderer_;  // null unless the algorithm has make_renderer
  std::vector<SceneTriangle> valid_;         // a batch's accepted triangles when some are refused
};

/// Draws one batch: a BatchDrawer made for it. Returns how many triangles were refused.
std::size_t draw_triangles(const TriangleAlgorithm& algorithm, Canvas& canvas,
                           std::span<const SceneTriangle> triangles);

/// The pixel centre nearest to p (halves round up), which is what the articles' integer
/// algorithms receive. Precondition: p is finite and within ±2^30.
glm::ivec2 nearest_pixel(glm::dvec2 p) noexcept;

/// A fill as the articles write it: three whole-pixel vertices and a colour.
using PixelTriangleFill = void (*)(Canvas&, glm::ivec2, glm::ivec2, glm::ivec2, Color);

/// The registry's entry point for an article's fill: each vertex is rounded to its nearest pixel
/// centre (nearest_pixel), since the articles' fills take whole pixels.
template <PixelTriangleFill fill>
void draw_at_nearest_pixels(Canvas& canvas, const Triangle& triangle, Color color) {
  fill(canvas, nearest_pixel(triangle[0]), nearest_pixel(triangle[1]), nearest_pixel(triangle[2]),
       color);
}

}  // namespace tri
