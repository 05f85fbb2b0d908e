#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "measure/peers/byte_coverage_peer.hpp"
#include "measure/peers/library_peers.hpp"

namespace tri {
namespace {

// FreeType's outlines hold 26.6 fixed point: a coordinate to the nearest 1/64 of a pixel.
FT_Pos to_26_6(double v) noexcept {
  return static_cast<FT_Pos>(std::lround(v * 64.0));
}

// A gray image drawn by FreeType's smooth rasterizer, one outline per triangle, through its
// span callback: each span's coverage (0 to 255) is added, saturating, as an A8 image with the
// ADD operator would take it. Row 0 of the image is the top.
class FreeTypeImage {
 public:
  FreeTypeImage(int width, int height)
      : width_(width),
        height_(height),
        pixels_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0) {
    if (FT_Init_FreeType(&library_) != 0) throw std::runtime_error("FreeType could not start");
  }
  ~FreeTypeImage() { FT_Done_FreeType(library_); }
  FreeTypeImage(const FreeTypeImage&) = delete;  // the library handle is owned once
  FreeTypeImage& operator=(const FreeTypeImage&) = delete;

  void clear() noexcept { std::fill(pixels_.begin(), pixels_.end(), std::uint8_t{0}); }

  void draw(const YDownTriangle& v) {
    // FreeType's y axis points up from the image's bottom edge: y_up = height - y_down.
    FT_Vector points[3];
    for (int i = 0; i < 3; ++i) points[i] = {to_26_6(v[i].x), to_26_6(height_ - v[i].y)};
    std::remove_pointer_t<decltype(FT_Outline::tags)> tags[3] = {FT_CURVE_TAG_ON, FT_CURVE_TAG_ON,
                                                                 FT_CURVE_TAG_ON};
    std::remove_pointer_t<decltype(FT_Outline::contours)> last_point[1] = {2};
    FT_Outline outline{};
    outline.n_contours = 1;
    outline.n_points = 3;
    outline.points = points;
    outline.tags = tags;
    outline.contours = last_point;
    outline.flags = FT_OUTLINE_NONE;  // non-zero winding: either orientation fills
    FT_Raster_Params params{};
    params.source = &outline;
    params.flags = FT_RASTER_FLAG_AA | FT_RASTER_FLAG_DIRECT | FT_RASTER_FLAG_CLIP;
    params.gray_spans = &FreeTypeImage::add_spans;
    params.user = this;
    params.clip_box = {0, 0, width_, height_};
    FT_Outline_Render(library_, &outline, &params);
  }

  std::uint8_t value(int x, int top_row) const noexcept {
    return pixels_[static_cast<std::size_t>(top_row) * static_cast<std::size_t>(width_) +
                   static_cast<std::size_t>(x)];
  }

 private:
  // FreeType hands the coverage of one row (y counted up from the bottom) as runs of pixels.
  static void add_spans(int y, int count, const FT_Span* spans, void* user) {
    auto& image = *static_cast<FreeTypeImage*>(user);
    const int top_row = image.height_ - 1 - y;
    if (top_row < 0 || top_row >= image.height_) return;
    std::uint8_t* row = image.pixels_.data() +
                        static_cast<std::size_t>(top_row) * static_cast<std::size_t>(image.width_);
    for (int s = 0; s < count; ++s) {
      const int begin = std::max(0, static_cast<int>(spans[s].x));
      const int end = std::min(image.width_, spans[s].x + static_cast<int>(spans[s].len));
      for (int x = begin; x < end; ++x) {
        row[x] = static_cast<std::uint8_t>(std::min(255, row[x] + spans[s].coverage));
      }
    }
  }

  int width_, height_;
  std::vector<std::uint8_t> pixels_;
  FT_Library library_ = nullptr;
};

}  // namespace

CoveragePeer freetype_coverage_peer() {
  return byte_coverage_peer<FreeTypeImage>(
      coverage_peer_description("freetype_smooth",
                                "FT_Outline_Render with FreeType's smooth rasterizer: the area "
                                "of the outline at 1/64-pixel coordinates, to 8 bits"),
      0, "FreeType", freetype_coordinate_limit);
}

std::string freetype_version() {
  FT_Library library = nullptr;
  if (FT_Init_FreeType(&library) != 0) return "FreeType (version unknown)";
  FT_Int major = 0, minor = 0, patch = 0;
  FT_Library_Version(library, &major, &minor, &patch);
  FT_Done_FreeType(library);
  return "FreeType " + std::to_string(major) + "." + std::to_string(minor) + "." +
         std::to_string(patch);
}

}  // namespace tri
