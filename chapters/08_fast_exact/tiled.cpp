#include "chapters/08_fast_exact/tiled.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <memory>
#include <system_error>
#include <thread>
#include <utility>

#include "chapters/07_exact_coverage/fixed_point.hpp"
#include "chapters/08_fast_exact/batched.hpp"
#include "chapters/08_fast_exact/blocks.hpp"
#include "chapters/08_fast_exact/hybrid.hpp"
#include "chapters/08_fast_exact/pixel_writers.hpp"
#include "chapters/08_fast_exact/threaded.hpp"

namespace tri::ch08 {
namespace {

// Chunks of the batch binned as one piece: enough for two or more threads to share the binning
// of a few large triangles, few enough that a tile's lists are quick to walk.
constexpr int max_chunks = 16;
// The largest canvas drawn in bands without binning: there, binning cost more than it saved
// (the performance notes measure it).
constexpr int cached_pixels = 512 * 512;
// An entry of a tile list with this bit set names a shared setup, not a triangle.
constexpr std::uint32_t shared_bit = std::uint32_t{1} << 31;

}  // namespace

ch05::PixelBox TileGrid::tile(int index, int width, int height) const noexcept {
  const int x = (index % columns) << width_bits, y = (index / columns) << height_bits;
  return {{x, y}, {std::min(x + tile_width(), width) - 1, std::min(y + tile_height(), height) - 1}};
}

// [listing tile_grid_for]
TileGrid tile_grid_for(int width, int height) noexcept {
  const auto grid = [&](int width_bits, int height_bits) {
    return TileGrid{width_bits, height_bits, ((width - 1) >> width_bits) + 1,
                    ((height - 1) >> height_bits) + 1};
  };
  // 512 x 64 pixels (128 KiB of RGBA8), halved in height down to 16 rows until the canvas has
  // 16 tiles, so that threads taking tiles one by one end close together.
  int height_bits = 6;
  while (height_bits > 4 && grid(9, height_bits).count() < 16) --height_bits;
  return grid(9, height_bits);
}
// [/listing]

void TileBins::start(std::span<const SceneTriangle> triangles, int width, int height, int bands) {
  triangles_ = triangles;
  width_ = width;
  height_ = height;
  if (bands > 0) {
    // One tile column as wide as the canvas, rows of tiles as tall as `bands` of them need.
    int width_bits = 3, height_bits = 3;
    while ((1 << width_bits) < width) ++width_bits;
    while ((((height - 1) >> height_bits) + 1) > bands) ++height_bits;
    grid_ = {width_bits, height_bits, 1, ((height - 1) >> height_bits) + 1};
    chunk_count_ = 0;
    return;
  }
  grid_ = tile_grid_for(width, height);
  const std::size_t count = triangles.size();
  chunk_count_ = static_cast<int>(std::clamp<std::size_t>(count, 1, max_chunks));
  if (chunk_storage_.size() < static_cast<std::size_t>(chunk_count_)) {
    chunk_storage_.resize(static_cast<std::size_t>(chunk_count_));
  }
  const std::size_t per_chunk =
      (count + static_cast<std::size_t>(chunk_count_) - 1) / static_cast<std::size_t>(chunk_count_);
  for (int c = 0; c < chunk_count_; ++c) {
    Chunk& chunk = chunk_storage_[static_cast<std::size_t>(c)];
    chunk.first_triangle = static_cast<std::uint32_t>(std::min(count, per_chunk * c));
    chunk.end_triangle = static_cast<std::uint32_t>(std::min(count, per_chunk * (c + 1)));
    const std::size_t size = chunk.end_triangle - chunk.first_triangle;
    chunk.starts.assign(static_cast<std::size_t>(grid_.count()) + 1, 0);
    chunk.footprints.resize(size);
    // Reserved so that binning never allocates: at most one shared setup per triangle.
    chunk.shared.clear();
    chunk.shared.reserve(size);
  }
}

// The tiles of a box of pixels; none (first column past the last) when the box is empty.
TileBins::Footprint TileBins::footprint(const ch05::PixelBox& pixels) const noexcept {
  if (pixels.empty()) return {1, 0, 0, 0, 0};
  return {static_cast<std::uint16_t>(pixels.min.x >> grid_.width_bits),
          static_cast<std::uint16_t>(pixels.min.y >> grid_.height_bits),
          static_cast<std::uint16_t>(pixels.max.x >> grid_.width_bits),
          static_cast<std::uint16_t>(pixels.max.y >> grid_.height_bits), 0};
}

template <class Visit>
void TileBins::for_each_tile_of(const Chunk& chunk, const Footprint& footprint,
                                Visit&& visit) const {
  if (footprint.first_column > footprint.last_column) return;  // no candidate pixels
  if (footprint.shared == 0) {                                 // within one tile
    visit(footprint.first_row * grid_.columns + footprint.first_column);
    return;
  }
  // Over several tiles: only those that no edge of the triangle excludes.
  const TriangleSetup& setup = chunk.shared[footprint.shared & ~shared_bit].setup;
  for (int row = footprint.first_row; row <= footprint.last_row; ++row) {
    for (int column = footprint.first_column; column <= footprint.last_column; ++column) {
      const int tile = row * grid_.columns + column;
      const ch05::PixelBox box = grid_.tile(tile, width_, height_);
      const ch05::PixelBox& r = setup.range;
      const ch05::PixelBox part{{std::max(box.min.x, r.min.x), std::max(box.min.y, r.min.y)},
                                {std::min(box.max.x, r.max.x), std::min(box.max.y, r.max.y)}};
      if (classify_block(setup, part) != BlockCoverage::outside) visit(tile);
    }
  }
}

// [listing bin_chunk]
void TileBins::bin_chunk(int chunk_index) noexcept {
  Chunk& chunk = chunk_storage_[static_cast<std::size_t>(chunk_index)];
  const std::uint32_t first = chunk.first_triangle;
  // First pass: each triangle's tiles, the full setup only for a triangle over several tiles,
  // and the count per tile.
  for (std::uint32_t i = first; i < chunk.end_triangle; ++i) {
    const Triangle& t = triangles_[i].vertices;
    const ch05::PixelBox around = pixels_around(t, width_, height_);
    Footprint f = footprint(around);
    // Asked of the box, not of f: comparing f's 16-bit fields just stored made GCC reload them
    // as one 32-bit word, which stalls.
    if (!around.empty() && ((around.min.x ^ around.max.x) >> grid_.width_bits ||
                            (around.min.y ^ around.max.y) >> grid_.height_bits)) {
      const auto setup = setup_triangle(t, width_, height_);
      f = footprint(setup ? setup->range : ch05::PixelBox{{1, 0}, {0, 0}});
      if (setup) {
        f.shared = static_cast<std::uint32_t>(chunk.shared.size()) | shared_bit;
        chunk.shared.push_back({*setup, i});  // within the capacity start() reserved
      }
    }
    chunk.footprints[i - first] = f;
    for_each_tile_of(chunk, f, [&](int tile) { ++chunk.starts[static_cast<std::size_t>(tile)]; });
  }
  // The counts become each tile's first entry, then a second pass lists the entries.
  std::uint32_t total = 0;
  for (std::uint32_t& start : chunk.starts) total += std::exchange(start, total);
  chunk.entries.resize(total);
  for (std::uint32_t i = first; i < chunk.end_triangle; ++i) {
    const Footprint& f = chunk.footprints[i - first];
    const std::uint32_t entry = f.shared == 0 ? i : f.shared;
    for_each_tile_of(chunk, f, [&](int tile) {
      chunk.entries[chunk.starts[static_cast<std::size_t>(tile)]++] = entry;
    });
  }
  // Each start was moved to the next tile's: shift them back.
  for (std::size_t tile = chunk.starts.size() - 1; tile > 0; --tile)
    chunk.starts[tile] = chunk.starts[tile - 1];
  chunk.starts[0] = 0;
}
// [/listing]

template <class Within, class Over>
void TileBins::for_each_triangle_of(int tile, Within&& within, Over&& over) const {
  if (chunk_count_ == 0) {
    // Not binned: every triangle of the batch, kept by its rows.
    const ch05::PixelBox box = grid_.tile(tile, width_, height_);
    // Snapping moves a vertex by at most 1/512 pixel, and a candidate row lies between the
    // snapped lowest and highest y: half a pixel of margin decides in doubles, without snapping.
    const double top = box.min.y - 0.5, bottom = box.max.y + 0.5;
    for (std::uint32_t i = 0; i < triangles_.size(); ++i) {
      const Triangle& t = triangles_[i].vertices;
      const double low = std::min(t[0].y, std::min(t[1].y, t[2].y));
      const double high = std::max(t[0].y, std::max(t[1].y, t[2].y));
      if (high < top || low > bottom) continue;
      if (low >= top && high <= bottom) {
        within(i);
      } else if (const auto setup = setup_triangle(triangles_[i].vertices, width_, height_)) {
        over(*setup, i);
      }
    }
    return;
  }
  const auto t = static_cast<std::size_t>(tile);
  for (int c = 0; c < chunk_count_; ++c) {
    const Chunk& chunk = chunk_storage_[static_cast<std::size_t>(c)];
    for (std::uint32_t e = chunk.starts[t]; e < chunk.starts[t + 1]; ++e) {
      const std::uint32_t entry = chunk.entries[e];
      if (entry & shared_bit) {
        const Shared& shared = chunk.shared[entry & ~shared_bit];
        over(shared.setup, shared.triangle);
      } else {
        within(entry);
      }
    }
  }
}

std::vector<std::uint32_t> TileBins::triangles_of(int tile) const {
  std::vector<std::uint32_t> triangles;
  for_each_triangle_of(
      tile, [&](std::uint32_t i) { triangles.push_back(i); },
      [&](const TriangleSetup&, std::uint32_t i) { triangles.push_back(i); });
  return triangles;
}

// [listing draw_tile]
template <class Writer>
void TileBins::draw_tile_with(Canvas& canvas, int tile) const noexcept {
  const ch05::PixelBox box = grid_.tile(tile, width_, height_);
  // The writers' row end keeps step 5's eight-pixel blends inside the tile.
  const int row_end = box.max.x + 1;
  // Triangles within this tile wait here to be set up eight at once (step 10's lanes) by the
  // thread that draws the tile; one over several tiles first draws those before it, in order.
  // Consecutive ones (most of a mesh's) are set up where they lie, others from a copy.
  std::array<std::uint32_t, setup_lanes> waiting;
  std::size_t waiting_count = 0;
  std::array<SceneTriangle, setup_lanes> copies;
  SetupLanes lanes;
  const auto draw_waiting = [&] {
    std::span<const SceneTriangle> group = triangles_.subspan(waiting[0], waiting_count);
    if (waiting[waiting_count - 1] - waiting[0] != waiting_count - 1) {
      for (std::size_t k = 0; k < waiting_count; ++k) copies[k] = triangles_[waiting[k]];
      group = std::span(copies).first(waiting_count);
    }
    draw_group<Writer>(canvas, group, row_end, lanes);
    waiting_count = 0;
  };
  for_each_triangle_of(
      tile,
      [&](std::uint32_t i) {
        waiting[waiting_count++] = i;
        if (waiting_count == setup_lanes) draw_waiting();
      },
      [&](const TriangleSetup& setup, std::uint32_t i) {
        if (waiting_count > 0) draw_waiting();
        // Clipped to the tile, which moves its origin by whole pixels.
        const auto part = clip_setup(setup, box);
        Writer writer(canvas, triangles_[i].color, row_end);
        if (part) fill_hybrid(*part, writer);
      });
  if (waiting_count > 0) draw_waiting();
}
// [/listing]

void TileBins::draw_tile(Canvas& canvas, int tile) const noexcept {
  with_writer_type(canvas, [&]<class Writer>() { draw_tile_with<Writer>(canvas, tile); });
}

TiledRenderer::TiledRenderer(int threads) {
  helpers_.reserve(static_cast<std::size_t>(std::max(threads - 1, 0)));
  try {
    while (static_cast<int>(helpers_.size()) < threads - 1) {
      helpers_.emplace_back([this] { help(); });
    }
  } catch (const std::system_error&) {
    // No more threads to be had: the ones running take all the chunks and tiles.
  }
  threads_ = static_cast<int>(helpers_.size()) + 1;
}

TiledRenderer::~TiledRenderer() {
  stopping_ = true;
  batches_.fetch_add(1);
  batches_.notify_all();
  // Each std::jthread of helpers_ joins as the member is destroyed, before the others.
}

// [listing tiled_work]
void TiledRenderer::work() noexcept {
  const int chunks = bins_.chunks(), tiles = bins_.grid().count();
  for (int c = next_chunk_.fetch_add(1); c < chunks; c = next_chunk_.fetch_add(1)) {
    bins_.bin_chunk(c);
    if (binned_.fetch_add(1) + 1 == chunks) binned_.notify_all();
  }
  // A tile needs every chunk: wait for the chunks other threads are still binning.
  for (int done = binned_.load(); done < chunks; done = binned_.load()) binned_.wait(done);
  for (int tile = next_tile_.fetch_add(1); tile < tiles; tile = next_tile_.fetch_add(1))
    bins_.draw_tile(*canvas_, tile);
}

void TiledRenderer::open(Canvas& canvas, std::span<const SceneTriangle> triangles) {
  // A small canvas gains nothing from binning: one band of rows per thread.
  const bool cached = canvas.width() * canvas.height() <= cached_pixels;
  bins_.start(triangles, canvas.width(), canvas.height(), cached ? threads_ : 0);
  canvas_ = &canvas;
  next_chunk_ = 0;
  binned_ = 0;
  next_tile_ = 0;
}

void TiledRenderer::draw(Canvas& canvas, std::span<const SceneTriangle> triangles) {
  open(canvas, triangles);
  inside_.fetch_and(~closed);  // open the batch to the helpers, and wake them
  batches_.fetch_add(1);
  batches_.notify_all();
  work();
  // Close it, then wait for every helper that joined to leave: none reads the batch after.
  inside_.fetch_or(closed);
  for (int now = inside_.load(); now != closed; now = inside_.load()) inside_.wait(now);
}

void TiledRenderer::help() noexcept {
  for (unsigned seen = 0;;) {
    batches_.wait(seen);
    seen = batches_.load();
    if (stopping_) return;
    // Joining counts this helper in; a batch already closed is left alone (a late wake-up).
    if (!(inside_.fetch_add(1) & closed)) work();
    inside_.fetch_sub(1);
    inside_.notify_all();
  }
}
// [/listing]

std::unique_ptr<BatchRenderer> make_tiled_renderer() {
  return std::make_unique<TiledRenderer>(hardware_threads());
}

}  // namespace tri::ch08
