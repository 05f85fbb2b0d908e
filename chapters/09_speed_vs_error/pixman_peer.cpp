#include "chapters/09_speed_vs_error/pixman_peer.hpp"

#include <pixman.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <numeric>
#include <vector>

#include "chapters/09_speed_vs_error/y_down_peer.hpp"

namespace tri::ch09 {
namespace {

// A one-bit image whose bits we own, so they can be cleared and read directly.
class PixmanMask {
 public:
  PixmanMask(int width, int height)
      : width_(width),
        height_(height),
        words_per_row_((width + 31) / 32),
        bits_(static_cast<std::size_t>(words_per_row_) * static_cast<std::size_t>(height)),
        image_(pixman_image_create_bits(PIXMAN_a1, width, height, bits_.data(), words_per_row_ * 4),
               pixman_image_unref) {
    if (!image_)
      throw std::runtime_error("pixman could not create a " + std::to_string(width) + "x" +
                               std::to_string(height) + " a1 image");
  }

  void clear() noexcept { std::fill(bits_.begin(), bits_.end(), 0u); }
  void add(const pixman_triangle_t& triangle) noexcept {
    pixman_add_triangles(image_.get(), 0, 0, 1, &triangle);
  }
  // Pixel (x, row) counted from the top row; pixman stores a1 pixels lowest bit first on
  // little-endian machines (the only kind this tutorial builds for).
  bool is_set(int x, int row) const noexcept {
    const std::uint32_t word =
        bits_[static_cast<std::size_t>(row) * static_cast<std::size_t>(words_per_row_) +
              static_cast<std::size_t>(x / 32)];
    return (word >> (x % 32)) & 1u;
  }

 private:
  int width_, height_, words_per_row_;
  std::vector<std::uint32_t> bits_;
  std::unique_ptr<pixman_image_t, pixman_bool_t (*)(pixman_image_t*)> image_;
};

pixman_triangle_t to_pixman(const SceneTriangle& triangle, int height) {
  pixman_point_fixed_t points[3];
  for (int i = 0; i < 3; ++i) {
    const glm::dvec2 p = to_y_down(triangle.vertices[i], height);
    // Exact for the suites' grids: 1/256 is a whole number of pixman's 1/65536 steps.
    points[i] = {pixman_double_to_fixed(p.x), pixman_double_to_fixed(p.y)};
  }
  return {points[0], points[1], points[2]};
}

std::vector<pixman_triangle_t> to_pixman(std::span<const SceneTriangle> triangles, int height) {
  require_within(triangles, height, pixman_coordinate_limit, "pixman");
  std::vector<pixman_triangle_t> out;
  out.reserve(triangles.size());
  for (const SceneTriangle& t : triangles) out.push_back(to_pixman(t, height));
  return out;
}

}  // namespace

WriteCounts pixman_write_counts(int width, int height, std::span<const SceneTriangle> triangles) {
  const std::vector<pixman_triangle_t> converted = to_pixman(triangles, height);
  PixmanMask mask(width, height);
  WriteCounts result;
  result.counts.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0);
  for (std::size_t t = 0; t < converted.size(); ++t) {
    mask.clear();
    mask.add(converted[t]);
    const PixelWindow window = pixels_around(triangles[t], width, height);
    for (int y = window.y_begin; y < window.y_end; ++y) {
      for (int x = window.x_begin; x < window.x_end; ++x) {
        if (mask.is_set(x, height - 1 - y)) {
          ++result.counts[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                          static_cast<std::size_t>(x)];
        }
      }
    }
  }
  return result;
}

namespace {

// As for the book's algorithms: image and converted triangles ready before the clock; one
// pixman call per triangle inside it.
Timing time_pixman_draw(const PreparedScene& prepared, const TimingPlan& plan) {
  const std::vector<pixman_triangle_t> triangles =
      to_pixman(prepared.triangles, prepared.scene.height);
  PixmanMask mask(prepared.scene.width, prepared.scene.height);
  // [listing pixman_timed_draw]
  return time_runs(
      [&] {
        for (const pixman_triangle_t& t : triangles) mask.add(t);
      },
      plan);
  // [/listing]
}

}  // namespace

ExternalPeer pixman_peer() {
  return {"pixman_a1",
          "external",
          "top-left",
          false,
          [](const PreparedScene& prepared, const TimingPlan& plan) {
            PeerResult result;
            result.timing = time_pixman_draw(prepared, plan);
            const WriteCounts drawn = pixman_write_counts(
                prepared.scene.width, prepared.scene.height, prepared.triangles);
            result.written_pixels =
                std::accumulate(drawn.counts.begin(), drawn.counts.end(), std::uint64_t{0});
            result.error = measure_error(pixman_write_counts, prepared.error_scene);
            return result;
          },
          time_pixman_draw};
}

}  // namespace tri::ch09
