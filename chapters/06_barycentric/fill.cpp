#include "chapters/06_barycentric/fill.hpp"

#include <algorithm>
#include <cmath>

#include "chapters/05_edge_function/bounding_box.hpp"
#include "chapters/06_barycentric/barycentric.hpp"

namespace tri::ch06 {
namespace {

// [listing fill_box_by_weights]
// The article's loop: every pixel of the clamped box, kept when its weights pass is_inside.
// Weighing is barycentric or barycentric_unguarded; the box bounds the loop to the canvas.
template <typename Weighing>
void fill_box_by_weights(Canvas& canvas, glm::ivec2 a, glm::ivec2 b, glm::ivec2 c, Color color,
                         Weighing weigh) noexcept {
  const ch05::PixelBox box = ch05::bounding_box_on_canvas(a, b, c, canvas.width(), canvas.height());
  for (int y = box.min.y; y <= box.max.y; ++y) {
    for (int x = box.min.x; x <= box.max.x; ++x) {
      if (is_inside(weigh(a, b, c, glm::ivec2(x, y)))) canvas.put_pixel(x, y, color);
    }
  }
}
// [/listing]

// [listing blend_channel]
std::uint8_t blend_channel(const Weights<double>& w, int channel_a, int channel_b, int channel_c) {
  const double value = w.x * channel_a + w.y * channel_b + w.z * channel_c;
  // Weights may miss [0, 1] by a rounding error; keep the channel a valid byte.
  return static_cast<std::uint8_t>(std::lround(std::clamp(value, 0.0, 255.0)));
}
// [/listing]

}  // namespace

// [listing fill_triangle_barycentric]
template <std::floating_point Scalar>
void fill_triangle_barycentric(Canvas& canvas, glm::ivec2 a, glm::ivec2 b, glm::ivec2 c,
                               Color color) noexcept {
  fill_box_by_weights(canvas, a, b, c, color, barycentric<Scalar>);
}
// [/listing]

template <std::floating_point Scalar>
void fill_triangle_barycentric_unguarded(Canvas& canvas, glm::ivec2 a, glm::ivec2 b, glm::ivec2 c,
                                         Color color) noexcept {
  fill_box_by_weights(canvas, a, b, c, color, barycentric_unguarded<Scalar>);
}

// [listing fill_triangle_with_weights]
void fill_triangle_with_weights(Canvas& canvas, glm::ivec2 a, glm::ivec2 b, glm::ivec2 c,
                                Color color_a, Color color_b, Color color_c) noexcept {
  const ch05::PixelBox box = ch05::bounding_box_on_canvas(a, b, c, canvas.width(), canvas.height());
  for (int y = box.min.y; y <= box.max.y; ++y) {
    for (int x = box.min.x; x <= box.max.x; ++x) {
      const Weights<double> w = barycentric<double>(a, b, c, glm::ivec2(x, y));
      if (!is_inside(w)) continue;
      canvas.put_pixel(x, y,
                       Color{blend_channel(w, color_a.r, color_b.r, color_c.r),
                             blend_channel(w, color_a.g, color_b.g, color_c.g),
                             blend_channel(w, color_a.b, color_b.b, color_c.b), 255});
    }
  }
}
// [/listing]

template void fill_triangle_barycentric<float>(Canvas&, glm::ivec2, glm::ivec2, glm::ivec2,
                                               Color) noexcept;
template void fill_triangle_barycentric<double>(Canvas&, glm::ivec2, glm::ivec2, glm::ivec2,
                                                Color) noexcept;
template void fill_triangle_barycentric_unguarded<float>(Canvas&, glm::ivec2, glm::ivec2,
                                                         glm::ivec2, Color) noexcept;
template void fill_triangle_barycentric_unguarded<double>(Canvas&, glm::ivec2, glm::ivec2,
                                                          glm::ivec2, Color) noexcept;

}  // namespace tri::ch06
