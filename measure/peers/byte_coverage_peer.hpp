/// @file
/// What the anti-aliasing peers share: each draws a triangle's coverage into a one-byte-per-pixel
/// image of its own (row 0 at the top, 255 for a full pixel), one library call per triangle, and
/// is timed and compared with the exact area the same way.
#pragma once

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <span>
#include <string>
#include <utility>

#include "measure/peers/peer.hpp"
#include "measure/peers/y_down_peer.hpp"

namespace tri {

/// A library's coverage image: built for a width x height canvas, cleared, drawn into one
/// triangle at a time (its vertices already in the library's y-down space), read as bytes.
template <class Image>
concept ByteCoverageImage = requires(Image image, const YDownTriangle& t, int x, int top_row) {
  {image.clear()};
  {image.draw(t)};
  { image.value(x, top_row) } -> std::convertible_to<std::uint8_t>;
};

/// Adds the image's coverage (value / 255) in the window to the canvas.
template <ByteCoverageImage Image>
void add_image_coverage(Image& image, ch09::CoverageCanvas& canvas, const PixelWindow& window) {
  for (int y = window.y_begin; y < window.y_end; ++y) {
    for (int x = window.x_begin; x < window.x_end; ++x) {
      const std::uint8_t v = image.value(x, canvas.height() - 1 - y);
      if (v != 0) canvas.add(x, y, static_cast<float>(v) / 255.0f);
    }
  }
}

/// The peer of `library`: an Image(width, height) of the canvas size, for scenes within
/// [-limit, limit] once mapped with to_y_down (require_within refuses the others). Timed: every
/// triangle of the scene drawn into one image, one call each, image ready before the clock.
/// Touched pixels: count_each_alone's writes. Error: measure_area_error with each triangle drawn
/// alone on a cleared image and read back in a window around it, then the whole scene.
template <ByteCoverageImage Image>
CoveragePeer byte_coverage_peer(const Drawable& description, int samples, std::string_view library,
                                double limit) {
  return {description, library, samples,
          [library = std::string(library), limit](const PreparedScene& prepared,
                                                  const AreaTruth& truth, const TimingPlan& plan) {
            const int width = prepared.scene.width, height = prepared.scene.height;
            require_within(prepared.triangles, height, limit, library);
            CoveragePeerResult result;
            {
              Image image(width, height);
              result.timing = time_runs(
                  [&] {
                    for (const SceneTriangle& t : prepared.triangles)
                      image.draw(to_y_down(t, height));
                  },
                  plan);
            }
            Image image(width, height);
            const WriteCounts touched = count_each_alone(
                width, height, std::span(prepared.triangles),
                [&](std::size_t t) {
                  image.clear();
                  image.draw(to_y_down(prepared.triangles[t], height));
                },
                [&](int x, int top_row) { return image.value(x, top_row) != 0; });
            result.touched_pixels =
                std::accumulate(touched.counts.begin(), touched.counts.end(), std::uint64_t{0});
            result.error = measure_area_error(
                [&](ch09::CoverageCanvas& canvas, std::span<const SceneTriangle> triangles) {
                  image.clear();
                  for (const SceneTriangle& t : triangles) image.draw(to_y_down(t, height));
                  const PixelWindow whole{0, width, 0, height};
                  add_image_coverage(image, canvas,
                                     triangles.size() == 1
                                         ? pixels_around(triangles.front(), width, height)
                                         : whole);
                },
                truth);
            return result;
          }};
}

}  // namespace tri
