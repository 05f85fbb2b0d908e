#include <pixman.h>

#include <memory>
#include <stdexcept>
#include <vector>

#include "chapters/09_speed_vs_error/byte_coverage_peer.hpp"
#include "chapters/09_speed_vs_error/library_peers.hpp"

namespace tri::ch09 {
namespace {

// An a8 image whose bytes we own; pixman_add_triangles adds each triangle's coverage into it.
class PixmanAlpha {
 public:
  PixmanAlpha(int width, int height)
      : height_(height),
        stride_((width + 3) / 4 * 4),  // pixman rows are whole 32-bit words
        bytes_(static_cast<std::size_t>(stride_) * static_cast<std::size_t>(height), 0),
        image_(pixman_image_create_bits(PIXMAN_a8, width, height,
                                        reinterpret_cast<std::uint32_t*>(bytes_.data()), stride_),
               pixman_image_unref) {
    if (!image_) throw std::runtime_error("pixman could not create an a8 image");
  }

  void clear() noexcept { std::fill(bytes_.begin(), bytes_.end(), std::uint8_t{0}); }
  void draw(const SceneTriangle& t) noexcept {
    pixman_point_fixed_t p[3];
    for (int i = 0; i < 3; ++i) {
      const glm::dvec2 v = to_y_down(t.vertices[i], height_);
      p[i] = {pixman_double_to_fixed(v.x), pixman_double_to_fixed(v.y)};
    }
    const pixman_triangle_t triangle{p[0], p[1], p[2]};
    pixman_add_triangles(image_.get(), 0, 0, 1, &triangle);
  }
  std::uint8_t value(int x, int top_row) const noexcept {
    return bytes_[static_cast<std::size_t>(top_row) * static_cast<std::size_t>(stride_) +
                  static_cast<std::size_t>(x)];
  }

 private:
  int height_, stride_;
  std::vector<std::uint8_t> bytes_;
  std::unique_ptr<pixman_image_t, pixman_bool_t (*)(pixman_image_t*)> image_;
};

}  // namespace

CoveragePeer pixman_coverage_peer() {
  return byte_coverage_peer<PixmanAlpha>("pixman_a8", "samples on a 15 x 17 grid", 255, "pixman",
                                         pixman_coordinate_limit);
}

}  // namespace tri::ch09
