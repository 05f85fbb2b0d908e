#include "chapters/08_fast_exact/threaded.hpp"

#include <algorithm>
#include <cstdint>
#include <system_error>
#include <thread>
#include <vector>

#include "chapters/08_fast_exact/hybrid.hpp"
#include "chapters/08_fast_exact/pixel_writers.hpp"
#include "chapters/08_fast_exact/triangle_setup.hpp"

namespace tri::ch08 {
namespace {

// Whether a band of `thread` holds a row of the triangle's candidate pixels, for a fraction of
// setup_triangle's work, so that every thread does not pay the whole setup of every small
// triangle.
bool touches_bands_of(const Triangle& triangle, int height, const Bands& bands,
                      int thread) noexcept {
  const auto [first_row, last_row] = candidate_rows(triangle, height);
  if (first_row > last_row) return false;
  const int first_band = first_row / bands.rows;
  // Any `threads` bands in a row include one of every thread.
  const int last_band = std::min(last_row / bands.rows, first_band + bands.threads - 1);
  for (int band = first_band; band <= last_band; ++band) {
    if (band % bands.threads == thread) return true;
  }
  return false;
}

// [listing draw_bands]
template <PixelWriter Writer>
void draw_bands(Canvas& canvas, std::span<const SceneTriangle> triangles, int thread, int threads) {
  const ch05::PixelBox whole{{0, 0}, {canvas.width() - 1, canvas.height() - 1}};
  const Bands bands = bands_for(canvas.height(), threads);
  for (const SceneTriangle& triangle : triangles) {
    if (threads > 1 && !touches_bands_of(triangle.vertices, canvas.height(), bands, thread)) {
      continue;
    }
    const auto setup = setup_triangle(triangle.vertices, canvas.width(), canvas.height());
    if (!setup) continue;
    Writer writer(canvas, triangle.color);
    if (threads == 1) {
      fill_hybrid(*setup, writer);
      continue;
    }
    // The first band of the triangle that belongs to this thread, then every threads-th one.
    const int first_band = setup->range.min.y / bands.rows;
    const int last_band = setup->range.max.y / bands.rows;
    for (int band = first_band + (thread - first_band % threads + threads) % threads;
         band <= last_band; band += threads) {
      const ch05::PixelBox rows{{whole.min.x, band * bands.rows},
                                {whole.max.x, band * bands.rows + bands.rows - 1}};
      if (const auto part = clip_setup(*setup, rows)) fill_hybrid(*part, writer);
    }
  }
}
// [/listing]

}  // namespace

void draw_bands_of_thread(Canvas& canvas, std::span<const SceneTriangle> triangles, int thread,
                          int threads) noexcept {
  with_writer_type(canvas,
                   [&]<class Writer>() { draw_bands<Writer>(canvas, triangles, thread, threads); });
}

// [listing draw_batch_on_threads]
void draw_batch_on_threads(Canvas& canvas, std::span<const SceneTriangle> triangles, int threads) {
  threads = std::max(threads, 1);
  // No more threads than bands (fewer threads only make the bands taller).
  const int rows = bands_for(canvas.height(), threads).rows;
  threads = std::min(threads, (canvas.height() + rows - 1) / rows);
  std::vector<std::jthread> workers;
  workers.reserve(static_cast<std::size_t>(threads - 1));
  int started = 1;
  try {
    for (; started < threads; ++started) {
      workers.emplace_back([&canvas, triangles, started, threads] {
        draw_bands_of_thread(canvas, triangles, started, threads);
      });
    }
  } catch (const std::system_error&) {
    // No more threads to be had: the bands of the ones not started are drawn below.
  }
  draw_bands_of_thread(canvas, triangles, 0, threads);
  for (int thread = started; thread < threads; ++thread)
    draw_bands_of_thread(canvas, triangles, thread, threads);
  // Each std::jthread joins when `workers` goes out of scope.
}
// [/listing]

std::pair<int, int> candidate_rows(const Triangle& triangle, int height) noexcept {
  std::int64_t low = snap_to_256ths(triangle[0]).y, high = low;
  for (const glm::dvec2& v : {triangle[1], triangle[2]}) {
    const std::int64_t y = snap_to_256ths(v).y;
    low = std::min(low, y);
    high = std::max(high, y);
  }
  // Clamped to one row beyond the canvas on either side, so that both fit an int.
  const std::int64_t first_row = std::clamp<std::int64_t>(-((-low) >> subpixel_bits), 0, height);
  const std::int64_t last_row = std::clamp<std::int64_t>(high >> subpixel_bits, -1, height - 1);
  return {static_cast<int>(first_row), static_cast<int>(last_row)};
}

int hardware_threads() noexcept {
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

void draw_batch_threaded(Canvas& canvas, std::span<const SceneTriangle> triangles) {
  draw_batch_on_threads(canvas, triangles, hardware_threads());
}

}  // namespace tri::ch08
