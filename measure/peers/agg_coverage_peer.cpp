#include <agg_pixfmt_gray.h>
#include <agg_rasterizer_scanline_aa.h>
#include <agg_renderer_base.h>
#include <agg_renderer_scanline.h>
#include <agg_rendering_buffer.h>
#include <agg_scanline_u.h>

#include <vector>

#include "measure/peers/byte_coverage_peer.hpp"
#include "measure/peers/library_peers.hpp"

namespace tri {
namespace {

// A gray8 image with AGG's rasterizer and renderer on it; row 0 of the buffer is the top.
class AggImage {
 public:
  AggImage(int width, int height)
      : pixels_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0),
        buffer_(pixels_.data(), static_cast<unsigned>(width), static_cast<unsigned>(height), width),
        format_(buffer_),
        renderer_(format_) {
    rasterizer_.gamma(agg::gamma_none());  // coverage as computed: linear, no gamma curve
  }
  AggImage(const AggImage&) = delete;  // AGG's objects point at each other
  AggImage& operator=(const AggImage&) = delete;

  void clear() noexcept { std::fill(pixels_.begin(), pixels_.end(), std::uint8_t{0}); }
  // [listing agg_draw]
  void draw(const YDownTriangle& v) {
    rasterizer_.reset();
    rasterizer_.move_to_d(v[0].x, v[0].y);
    rasterizer_.line_to_d(v[1].x, v[1].y);
    rasterizer_.line_to_d(v[2].x, v[2].y);
    agg::render_scanlines_aa_solid(rasterizer_, scanline_, renderer_, agg::gray8(255));
  }
  // [/listing]
  std::uint8_t value(int x, int top_row) const noexcept {
    return pixels_[static_cast<std::size_t>(top_row) * buffer_.width() +
                   static_cast<std::size_t>(x)];
  }

 private:
  std::vector<std::uint8_t> pixels_;
  agg::rendering_buffer buffer_;
  agg::pixfmt_gray8 format_;
  agg::renderer_base<agg::pixfmt_gray8> renderer_;
  agg::rasterizer_scanline_aa<> rasterizer_;
  agg::scanline_u8 scanline_;
};

}  // namespace

CoveragePeer agg_coverage_peer() {
  return byte_coverage_peer<AggImage>(
      coverage_peer_description("agg_scanline_aa",
                                "agg::rasterizer_scanline_aa: the exact area, cut to 8 bits"),
      0, "AGG", agg_coordinate_limit);
}

}  // namespace tri
