/// @file
/// Step 7 · threads: the canvas cut into bands of rows dealt round-robin to the threads; each
/// thread draws every triangle of the batch, in order, clipped to its own bands, so the picture
/// is the serial one pixel for pixel and no two threads ever write the same pixel.
#pragma once

#include <span>
#include <utility>

#include "common/canvas.hpp"
#include "common/color.hpp"
#include "common/scene.hpp"
#include "common/triangle_algorithm.hpp"

namespace tri::ch08 {

/// How the rows are shared: bands of `rows` rows, band k drawn by thread k mod `threads`.
struct Bands {
  int rows;
  int threads;

  /// The thread (0 <= owner < threads) that draws row y.
  constexpr int owner(int y) const noexcept { return (y / rows) % threads; }
};

/// The bands for a canvas `height` rows tall and `threads` threads: about four bands per thread,
/// 16 to 64 rows each, a multiple of 8. Each band a triangle touches restarts its spans (six
/// divisions), so bands should be tall; each thread should get several, so that a large triangle
/// is shared out evenly. On 512 rows, two threads get 64-row bands.
constexpr Bands bands_for(int height, int threads) noexcept {
  const int rows = height / (4 * threads) / 8 * 8;
  return {rows < 16 ? 16 : (rows > 64 ? 64 : rows), threads};
}

/// The rows that can hold a candidate pixel of the triangle once snapped (setup_triangle's row
/// range, from the snapped y coordinates alone), clamped to a canvas `height` rows tall; the first
/// is past the last when there are none.
std::pair<int, int> candidate_rows(const Triangle& triangle, int height) noexcept;

/// The work of thread `thread` of `threads`: every triangle in order, each clipped to the bands
/// that bands_for(canvas height, threads) gives this thread. Writes only rows of those bands (and
/// their write counts).
void draw_bands_of_thread(Canvas& canvas, std::span<const SceneTriangle> triangles, int thread,
                          int threads) noexcept;

/// The threads a registered threaded entry starts: one per hardware thread, at least 1 (the
/// standard allows hardware_concurrency() to answer 0).
int hardware_threads() noexcept;

/// Draws the batch with `threads` threads (at least 1, at most one per band), created here and
/// joined before returning. If a thread cannot be started, the calling thread does its share.
void draw_batch_on_threads(Canvas& canvas, std::span<const SceneTriangle> triangles, int threads);

/// Step 7 · the registered batch entry: std::thread::hardware_concurrency() threads.
void draw_batch_threaded(Canvas& canvas, std::span<const SceneTriangle> triangles);

}  // namespace tri::ch08
