/// @file
/// Drawing a whole scene with one registered triangle algorithm.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <variant>
#include <vector>

#include "chapters/09_anti_aliasing/area_algorithms.hpp"
#include "common/canvas.hpp"
#include "common/scene.hpp"
#include "common/triangle_algorithm.hpp"

namespace tri {

/// What drawing a scene did.
struct RenderStats {
  std::size_t triangles = 0;           ///< triangles handed to the algorithm
  std::size_t lines = 0;               ///< lines drawn
  std::size_t rejected_triangles = 0;  ///< triangles refused by draw_triangle (NaN, range)
};

/// Hears how many primitives are done; within a triangle drawn in bands the count has a fraction.
using ProgressFunction = std::function<void(double done)>;

/// A triangle whose bounding box on the canvas holds more pixels than this is drawn in bands of
/// rows of about this many pixels when progress is reported (and its algorithm has draw_rows).
inline constexpr std::int64_t band_pixels = std::int64_t{1} << 20;

/// A canvas of the scene's size and background.
Canvas make_canvas(const Scene& scene);

/// Draws every primitive in file order: runs of consecutive triangles with the drawer (so
/// non-finite input is refused and batch algorithms get whole runs), lines with chapter 01's
/// Bresenham between the nearest pixel centres. The drawer may be null when the scene has no
/// triangles. With on_progress, runs are drawn in pieces sized to take about a tenth of a second,
/// and on_progress hears how many primitives are done after each piece; a huge triangle (more than
/// band_pixels) whose algorithm has draw_rows is drawn alone in bands of rows, with a report after
/// each band, and the same pixels. A caller that draws the scene many times keeps one drawer.
RenderStats render_scene(const Scene& scene, BatchDrawer* drawer, Canvas& canvas,
                         const ProgressFunction& on_progress = {});

/// A scene made ready once to be drawn many times: its runs of consecutive triangles, each a
/// PreparedBatch (copied out of the scene and checked once, culled to the scene's canvas), and the
/// lines between them, in order.
struct PreparedDrawing {
  std::vector<std::variant<PreparedBatch, SceneLine>> steps;
  RenderStats stats;  ///< what every draw of it does
};

/// Prepares a scene for draw_prepared: the one copy and check of its triangles, leaving out those
/// that cannot write a pixel of the scene's canvas (PreparedBatch's culling).
PreparedDrawing prepare_drawing(const Scene& scene);

/// Draws a prepared scene as render_scene draws the scene, pixel for pixel and write for write,
/// checking, copying and allocating nothing; returns the stats render_scene returns. The drawer
/// may be null when the scene has no triangles. The canvas is the scene's size or smaller.
RenderStats draw_prepared(const PreparedDrawing& prepared, BatchDrawer* drawer, Canvas& canvas);

/// The same with a drawer of the algorithm made for this one scene (null: no triangles).
RenderStats render_scene(const Scene& scene, const TriangleAlgorithm* algorithm, Canvas& canvas,
                         const ProgressFunction& on_progress = {});

/// Adds the coverage of the scene's triangles (lines have no area) to the canvas in pieces, so
/// no copy of all the triangles is made, with progress as render_scene's (bands through the
/// algorithm's draw_rows). Returns how many triangles were refused (non-finite or out of range).
std::size_t render_coverage(const Scene& scene, const ch09::AreaAlgorithm& algorithm,
                            ch09::CoverageCanvas& canvas, const ProgressFunction& on_progress = {});

/// Rows per band for a triangle whose bounding box on a width x height canvas holds more than
/// band_pixels pixels, so that a band holds about band_pixels; 0 for a smaller one (drawn whole).
int band_rows_for(const Triangle& triangle, int width, int height);

/// Calls draw_rows(first_row, last_row) for bands of `rows` rows that partition the canvas's rows
/// 0..height-1 in order: the first band ends `rows` rows into the triangle's bounding box, the last
/// takes the rest. after_band hears the share of the box's rows done. With an algorithm's
/// draw_rows entry this draws what its draw does, pixel for pixel and write for write.
void for_each_band(const Triangle& triangle, int width, int height, int rows,
                   const std::function<void(int first_row, int last_row)>& draw_rows,
                   const std::function<void(double share)>& after_band = {});

/// The scene's triangles in order, without its lines.
std::vector<SceneTriangle> scene_triangles(const Scene& scene);

/// Number of triangles in a scene.
std::size_t count_triangles(const Scene& scene);

}  // namespace tri
