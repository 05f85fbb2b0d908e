/// @file
/// Step 9 · threads over tiles: the batch binned once into tiles (every triangle listed
/// in the tiles it touches, in submission order), then each tile drawn whole by one thread,
/// tiles handed out one at a time, so the picture is the serial one pixel for pixel.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <memory>
#include <span>
#include <thread>
#include <vector>

#include "chapters/05_edge_function/bounding_box.hpp"
#include "chapters/08_fast_exact/triangle_setup.hpp"
#include "common/canvas.hpp"
#include "common/scene.hpp"
#include "common/triangle_algorithm.hpp"

namespace tri::ch08 {

/// The canvas cut into tiles of 2^width_bits x 2^height_bits pixels (multiples of 8), in rows
/// from the bottom; the last column and row of tiles are cut by the canvas border.
struct TileGrid {
  int width_bits;   ///< a tile is 2^width_bits pixels wide
  int height_bits;  ///< and 2^height_bits tall
  int columns;
  int rows;

  int tile_width() const noexcept { return 1 << width_bits; }
  int tile_height() const noexcept { return 1 << height_bits; }

  int count() const noexcept { return columns * rows; }
  /// The pixels of tile `index` (0 <= index < count()) on a width x height canvas.
  ch05::PixelBox tile(int index, int width, int height) const noexcept;
};

/// The tiles of a width x height canvas: 512 pixels wide and 64 rows tall (128 KiB of RGBA8,
/// a quarter of the 512 KiB level-2 cache each vCPU of this machine reports), or 32 or 16 rows on a
/// canvas that would otherwise have fewer than 16 tiles. Wide, because every tile a triangle
/// crosses restarts its spans and splits each row's span (the README measures narrower tiles).
TileGrid tile_grid_for(int width, int height) noexcept;

// [listing pixels_around]
/// A box of pixels that holds every candidate pixel of the triangle once snapped (chapter 07's
/// candidate_pixels), found in doubles without snapping: what binning needs of a small triangle.
/// Empty when the triangle is clearly off the canvas.
inline ch05::PixelBox pixels_around(const Triangle& t, int width, int height) noexcept {
  // Snapping moves a vertex by at most 1/512 pixel: half a pixel of margin holds every centre
  // the snapped triangle's candidate pixels can reach. Clamped before converting, so a vertex
  // at ±2^30 converts safely; a box that misses the canvas comes out empty.
  const auto low = [](double a, double b, double c) { return std::min(a, std::min(b, c)) - 0.5; };
  const auto high = [](double a, double b, double c) { return std::max(a, std::max(b, c)) + 0.5; };
  const double x0 = low(t[0].x, t[1].x, t[2].x), x1 = high(t[0].x, t[1].x, t[2].x);
  const double y0 = low(t[0].y, t[1].y, t[2].y), y1 = high(t[0].y, t[1].y, t[2].y);
  if (x1 < 0 || y1 < 0 || x0 > width - 1 || y0 > height - 1) return {{1, 0}, {0, 0}};
  const auto clamped = [](double v, int last) {
    return static_cast<int>(std::clamp(v, 0.0, static_cast<double>(last)));  // floor for v >= 0
  };
  return {{clamped(x0, width - 1), clamped(y0, height - 1)},
          {clamped(x1, width - 1), clamped(y1, height - 1)}};
}
// [/listing]

/// A batch binned into tiles. Built in chunks of triangles, which threads may bin at the same
/// time (one chunk each); each chunk lists, per tile, the entries of its triangles that touch the
/// tile, so a tile's triangles in submission order are its entries chunk after chunk. A triangle
/// within one tile is listed by its index and set up when the tile is drawn; a larger one is set
/// up once while binning, listed only in the tiles its edges do not exclude, and clipped to each.
///
/// Keep one TileBins across frames and its storage is reused: it allocates only when a batch
/// needs more than any before it (in start(), and for a chunk's list of entries once that
/// chunk is counted), never per triangle or per pixel.
class TileBins {
 public:
  /// Prepares the bins for `triangles` (kept by reference until the last draw_tile) on a
  /// width x height canvas. Not thread-safe; call before any bin_chunk. With `bands` > 0 nothing
  /// is binned (no chunks): the tiles are at most `bands` full-width bands of rows, and each
  /// tile's draw reads the whole batch and keeps the triangles whose rows reach it.
  void start(std::span<const SceneTriangle> triangles, int width, int height, int bands = 0);

  /// The number of chunks start() cut the batch into.
  int chunks() const noexcept { return chunk_count_; }
  const TileGrid& grid() const noexcept { return grid_; }

  /// Bins the triangles of chunk `chunk`. Threads may bin different chunks at once. Ends the
  /// program if the chunk's entries cannot be allocated (a thread has no one to throw to).
  void bin_chunk(int chunk) noexcept;

  /// The triangles listed in tile `tile`, in the order draw_tile draws them.
  std::vector<std::uint32_t> triangles_of(int tile) const;

  /// Draws tile `tile` of the canvas: every triangle binned there, in submission order, clipped
  /// to the tile. Needs every chunk binned. Writes only the tile's pixels (and their write
  /// counts), so threads may draw different tiles at once.
  void draw_tile(Canvas& canvas, int tile) const noexcept;

 private:
  // A triangle set up while binning: it touches more than one tile.
  struct Shared {
    TriangleSetup setup;
    std::uint32_t triangle;
  };
  // Where a triangle of a chunk falls: the tiles of its candidate pixels (none when the first
  // column is past the last) and, for one over several tiles, its entry (its slot among the
  // chunk's shared setups, with the top bit set); 0 for one within a single tile.
  struct Footprint {
    std::uint16_t first_column, first_row, last_column, last_row;
    std::uint32_t shared;
  };
  struct Chunk {
    std::uint32_t first_triangle = 0;
    std::uint32_t end_triangle = 0;
    std::vector<std::uint32_t> starts;  // per tile, its first entry; one more at the end
    std::vector<std::uint32_t> entries;
    std::vector<Shared> shared;
    std::vector<Footprint> footprints;  // per triangle of the chunk
  };
  template <class Writer>
  void draw_tile_with(Canvas& canvas, int tile) const noexcept;
  // Calls within(triangle index) or shared(its setup, its index) for each triangle of the tile,
  // in submission order: within a tile, or set up once over several.
  template <class Within, class Over>
  void for_each_triangle_of(int tile, Within&& within, Over&& over) const;
  Footprint footprint(const ch05::PixelBox& pixels) const noexcept;
  template <class Visit>
  void for_each_tile_of(const Chunk& chunk, const Footprint& footprint, Visit&& visit) const;

  std::span<const SceneTriangle> triangles_;
  int width_ = 0;
  int height_ = 0;
  TileGrid grid_{9, 6, 0, 0};
  int chunk_count_ = 0;
  std::vector<Chunk> chunk_storage_;
};

/// Step 9 · threads over tiles that last from batch to batch: the calling thread and
/// `threads` - 1 helpers, started by the constructor and joined by the destructor, which wait
/// for the next batch in between, and one TileBins reused by every batch.
///
/// For each batch the threads first take chunks to bin, then, once every chunk is binned, tiles
/// to draw, each from a shared counter. No chunk or tile belongs to a thread in advance, so a
/// helper that wakes late or is slowed down simply takes fewer; draw() returns once every helper
/// that took part has left. If a helper cannot be started, the others do its share.
class TiledRenderer final : public BatchRenderer {
 public:
  explicit TiledRenderer(int threads);
  ~TiledRenderer() override;
  TiledRenderer(const TiledRenderer&) = delete;
  TiledRenderer& operator=(const TiledRenderer&) = delete;

  /// Draws the batch as if one triangle after the other. On a canvas of at most 512 x 512 pixels
  /// the tiles are one band of rows per thread, not binned (TileBins::start). One batch at a
  /// time: draw() is not to be called from two threads at once.
  void draw(Canvas& canvas, std::span<const SceneTriangle> triangles) override;

 private:
  void open(Canvas& canvas, std::span<const SceneTriangle> triangles);  // bins and counters
  void work() noexcept;  // one thread's part of the current batch
  void help() noexcept;  // a helper's life: wait for a batch, take part, wait again

  // In `inside_` (helpers in the current batch): set while no batch is open to join.
  static constexpr int closed = 1 << 30;

  TileBins bins_;
  Canvas* canvas_ = nullptr;
  std::atomic<int> next_chunk_{0}, binned_{0}, next_tile_{0};
  std::atomic<unsigned> batches_{0};  // batches begun: the helpers wait for it to change
  std::atomic<int> inside_{closed};
  std::atomic<bool> stopping_{false};
  int threads_ = 1;                    // the calling thread and the helpers started
  std::vector<std::jthread> helpers_;  // the last member: joined before the others go
};

/// Step 9 · the registered renderer: a TiledRenderer with one thread per hardware thread
/// (hardware_threads()), kept by the caller's BatchDrawer for as many batches as it draws.
std::unique_ptr<BatchRenderer> make_tiled_renderer();

}  // namespace tri::ch08
