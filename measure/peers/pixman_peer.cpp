#include "measure/peers/library_peers.hpp"

#include <pixman.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "measure/peers/byte_coverage_peer.hpp"
#include "measure/peers/y_down_peer.hpp"

namespace tri {
namespace {

// Exact for the suites' grids: 1/256 is a whole number of pixman's 1/65536 steps.
pixman_triangle_t to_pixman(const YDownTriangle& v) noexcept {
  pixman_point_fixed_t points[3];
  for (int i = 0; i < 3; ++i) {
    points[i] = {pixman_double_to_fixed(v[i].x), pixman_double_to_fixed(v[i].y)};
  }
  return {points[0], points[1], points[2]};
}

std::vector<pixman_triangle_t> to_pixman(std::span<const SceneTriangle> triangles, int height) {
  require_within(triangles, height, pixman_coordinate_limit, "pixman");
  std::vector<pixman_triangle_t> out;
  out.reserve(triangles.size());
  for (const SceneTriangle& t : triangles) out.push_back(to_pixman(to_y_down(t, height)));
  return out;
}

// A one-channel pixman image (PIXMAN_a1 or PIXMAN_a8) whose bits we own, so they can be cleared
// and read directly. pixman_add_triangles sets an a1 pixel or adds coverage to an a8 one
// (saturating at 255).
class PixmanImage {
 public:
  PixmanImage(int width, int height, pixman_format_code_t format)
      : bits_per_pixel_(PIXMAN_FORMAT_BPP(format)),
        words_per_row_((width * bits_per_pixel_ + 31) / 32),  // rows are whole 32-bit words
        words_(static_cast<std::size_t>(words_per_row_) * static_cast<std::size_t>(height)),
        image_(pixman_image_create_bits(format, width, height, words_.data(), words_per_row_ * 4),
               pixman_image_unref) {
    if (!image_)
      throw std::runtime_error("pixman could not create a " + std::to_string(width) + "x" +
                               std::to_string(height) + " a" + std::to_string(bits_per_pixel_) +
                               " image");
  }

  void clear() noexcept { std::fill(words_.begin(), words_.end(), 0u); }
  void add(const pixman_triangle_t& triangle) noexcept { add(std::span(&triangle, 1)); }
  // Every triangle in one call, as a program drawing a frame would.
  void add(std::span<const pixman_triangle_t> triangles) noexcept {
    pixman_add_triangles(image_.get(), 0, 0, static_cast<int>(triangles.size()), triangles.data());
  }
  void draw(const YDownTriangle& v) noexcept { add(to_pixman(v)); }
  // Pixel (x, row) counted from the top row: 0 or 1 in a1, 0 to 255 in a8. pixman stores a1
  // pixels lowest bit first on little-endian machines (the only kind this tutorial builds for).
  std::uint8_t value(int x, int row) const noexcept {
    const auto* bytes =
        reinterpret_cast<const std::uint8_t*>(words_.data()) +
        static_cast<std::size_t>(row) * static_cast<std::size_t>(words_per_row_) * 4;
    if (bits_per_pixel_ == 1) return static_cast<std::uint8_t>((bytes[x / 8] >> (x % 8)) & 1u);
    return bytes[x];
  }

 private:
  int bits_per_pixel_, words_per_row_;
  std::vector<std::uint32_t> words_;
  std::unique_ptr<pixman_image_t, pixman_bool_t (*)(pixman_image_t*)> image_;
};

// The a8 image of the coverage peer.
struct PixmanAlpha : PixmanImage {
  PixmanAlpha(int width, int height) : PixmanImage(width, height, PIXMAN_a8) {}
};

}  // namespace

WriteCounts pixman_write_counts(int width, int height, std::span<const SceneTriangle> triangles) {
  const std::vector<pixman_triangle_t> converted = to_pixman(triangles, height);
  PixmanImage mask(width, height, PIXMAN_a1);
  return count_each_alone(
      width, height, triangles,
      [&](std::size_t t) {
        mask.clear();
        mask.add(converted[t]);
      },
      [&](int x, int top_row) { return mask.value(x, top_row) != 0; });
}

namespace {

// Image and converted triangles ready before the clock, as for the book's algorithms; inside it
// the whole frame in one pixman call, as a program that draws with pixman would make it.
Timing time_pixman_draw(const PreparedScene& prepared, const TimingPlan& plan) {
  const std::vector<pixman_triangle_t> triangles =
      to_pixman(prepared.triangles, prepared.scene.height);
  PixmanImage mask(prepared.scene.width, prepared.scene.height, PIXMAN_a1);
  // [listing pixman_timed_draw]
  return time_runs([&] { mask.add(triangles); }, plan);
  // [/listing]
}

}  // namespace

ExternalPeer pixman_peer() {
  return in_process_peer(
      aliased_peer_description(
          "pixman_a1", "pixman_add_triangles of the whole frame, one call, into a one-bit image",
          CoverageRule::top_left, false),
      "pixman", time_pixman_draw, pixman_write_counts);
}

CoveragePeer pixman_coverage_peer() {
  return byte_coverage_peer<PixmanAlpha>(
      coverage_peer_description("pixman_a8",
                                "pixman_add_triangles into an a8 image: samples on a 15 x 17 grid"),
      255, "pixman", pixman_coordinate_limit);
}

std::string pixman_version() {
  return std::string("pixman ") + pixman_version_string();
}

}  // namespace tri
