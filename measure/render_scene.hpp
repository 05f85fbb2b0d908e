/// @file
/// Drawing a whole scene with one registered triangle algorithm.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

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

/// A canvas of the scene's size and background.
Canvas make_canvas(const Scene& scene);

/// Draws every primitive in file order: runs of consecutive triangles with the drawer (so
/// non-finite input is refused and batch algorithms get whole runs), lines with chapter 01's
/// Bresenham between the nearest pixel centres. The drawer may be null when the scene has no
/// triangles. With on_progress, runs are drawn in pieces sized to take about a tenth of a second,
/// and on_progress hears how many primitives are done after each piece. A caller that draws the
/// scene many times keeps one drawer for all of them.
RenderStats render_scene(const Scene& scene, BatchDrawer* drawer, Canvas& canvas,
                         const std::function<void(std::size_t done)>& on_progress = {});

/// The same with a drawer of the algorithm made for this one scene (null: no triangles).
RenderStats render_scene(const Scene& scene, const TriangleAlgorithm* algorithm, Canvas& canvas,
                         const std::function<void(std::size_t done)>& on_progress = {});

/// The scene's triangles in order, without its lines.
std::vector<SceneTriangle> scene_triangles(const Scene& scene);

/// Number of triangles in a scene.
std::size_t count_triangles(const Scene& scene);

}  // namespace tri
