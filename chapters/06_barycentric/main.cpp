// Chapter 06's figures: tinyrenderer's three triangles with their bounding boxes, filled, and
// coloured by their barycentric weights; what a zero area draws without the guard; and where
// float and double part ways.
#include <array>

#include "barycentric.hpp"
#include "bounding_box.hpp"
#include "examples.hpp"
#include "figures.hpp"
#include "fill.hpp"

namespace {

using tri::Canvas;
using tri::Color;
using tri::ch06::PixelTriangle;

constexpr std::array<Color, 3> tinyrenderer_colors{tri::colors::red, tri::colors::white,
                                                   tri::colors::green};
constexpr Color dark_gray{60, 60, 60, 255};

Color darker(Color color) {
  return Color{color.r / 4, color.g / 4, color.b / 4, 255};
}

void fill_box(Canvas& canvas, const tri::ch05::PixelBox& box, Color color) {
  for (int y = box.min.y; y <= box.max.y; ++y) {
    for (int x = box.min.x; x <= box.max.x; ++x) canvas.put_pixel(x, y, color);
  }
}

// Step 1: each triangle over its bounding box, the pixels the loop visits.
Canvas bounding_boxes() {
  Canvas canvas(200, 200);
  for (std::size_t i = 0; i < 3; ++i) {
    const auto [a, b, c] = tri::ch06::tinyrenderer_triangles[i];
    fill_box(canvas, tri::ch05::bounding_box_on_canvas(a, b, c, canvas.width(), canvas.height()),
             darker(tinyrenderer_colors[i]));
  }
  for (std::size_t i = 0; i < 3; ++i) {
    const auto [a, b, c] = tri::ch06::tinyrenderer_triangles[i];
    tri::ch06::fill_triangle_barycentric<double>(canvas, a, b, c, tinyrenderer_colors[i]);
  }
  return canvas;
}

// Step 4: the three triangles filled, as tinyrenderer shows them.
Canvas tinyrenderer_triangles() {
  Canvas canvas(200, 200);
  for (std::size_t i = 0; i < 3; ++i) {
    const auto [a, b, c] = tri::ch06::tinyrenderer_triangles[i];
    tri::ch06::fill_triangle_barycentric<double>(canvas, a, b, c, tinyrenderer_colors[i]);
  }
  return canvas;
}

// Step 5: the same triangles, each pixel a blend of red, green and blue by its weights.
Canvas weights() {
  Canvas canvas(200, 200);
  for (const auto& [a, b, c] : tri::ch06::tinyrenderer_triangles) {
    tri::ch06::fill_triangle_with_weights(canvas, a, b, c, tri::colors::red, tri::colors::green,
                                          tri::colors::blue);
  }
  return canvas;
}

// Zero-area triangles: grey is the bounding box the loop visits, red what the unguarded version
// draws (NaN weights). The guarded version draws nothing here.
Canvas zero_area_unguarded() {
  Canvas canvas(12, 13);
  const std::array<PixelTriangle, 4> degenerate{{
      {{{1, 1}, {3, 2}, {9, 5}}},     // diagonal, direction (2, 1)
      {{{1, 8}, {10, 8}, {5, 8}}},    // horizontal
      {{{2, 10}, {2, 10}, {9, 11}}},  // two vertices equal, no pixel centre between the ends
      {{{10, 1}, {10, 1}, {10, 1}}},  // a point
  }};
  for (const auto& [a, b, c] : degenerate) {
    fill_box(canvas, tri::ch05::bounding_box_on_canvas(a, b, c, canvas.width(), canvas.height()),
             dark_gray);
  }
  for (const auto& [a, b, c] : degenerate) {
    tri::ch06::fill_triangle_barycentric_unguarded<double>(canvas, a, b, c, tri::colors::red);
    tri::ch06::fill_triangle_barycentric<double>(canvas, a, b, c, tri::colors::white);
  }
  return canvas;
}

// The kept triangle of the seeded search: white where both draw, red where only double does
// (float misses it), blue where only float does.
Canvas float_versus_double() {
  const auto [a, b, c] = tri::ch06::float_double_disagreement;
  Canvas with_float(16, 16), with_double(16, 16);
  with_float.enable_write_counts();
  with_double.enable_write_counts();
  tri::ch06::fill_triangle_barycentric<float>(with_float, a, b, c, tri::colors::white);
  tri::ch06::fill_triangle_barycentric<double>(with_double, a, b, c, tri::colors::white);
  Canvas canvas(16, 16);
  for (int y = 0; y < 16; ++y) {
    for (int x = 0; x < 16; ++x) {
      const bool f = with_float.write_count(x, y) > 0, d = with_double.write_count(x, y) > 0;
      if (f && d) canvas.put_pixel(x, y, tri::colors::white);
      if (d && !f) canvas.put_pixel(x, y, tri::colors::red);
      if (f && !d) canvas.put_pixel(x, y, tri::colors::blue);
    }
  }
  return canvas;
}

// A zero-area triangle 10^7 away, which double leaves empty and float draws because it computes
// the area as 2^21: white where float draws a pixel centre that lies exactly on the line, red
// where it draws one off the line.
Canvas float_zero_area_far_away() {
  const auto [a, b, c] = tri::ch06::collinear_at_ten_million;
  Canvas canvas(32, 32);
  tri::ch06::fill_triangle_barycentric<double>(canvas, a, b, c, tri::colors::yellow);
  tri::ch06::fill_triangle_barycentric<float>(canvas, a, b, c, tri::colors::red);
  // The line has direction (1, 7) through (16, 16): these are its pixel centres on the canvas.
  for (int k = -2; k <= 2; ++k) {
    if (canvas.pixel(16 + k, 16 + 7 * k) == tri::colors::red) {
      canvas.put_pixel(16 + k, 16 + 7 * k, tri::colors::white);
    }
  }
  return canvas;
}

}  // namespace

int main(int argc, char** argv) {
  return tri::run_chapter_program(
      argc, argv, "06_barycentric",
      "Chapter 06, bounding box and barycentric coordinates: tinyrenderer's three triangles over\n"
      "their bounding boxes (06_bounding_boxes.png), filled (06_tinyrenderer_triangles.png) and\n"
      "coloured by their weights (06_barycentric_weights.png); what zero-area triangles draw\n"
      "without the guard (06_zero_area_unguarded.png); the pixel float misses and double keeps\n"
      "(06_float_vs_double.png); a zero-area triangle 10^7 away that float draws\n"
      "(06_float_zero_area_far_away.png).",
      [](tri::FigureWriter& figures) {
        figures.save_png("06_bounding_boxes", tri::magnified(bounding_boxes(), 3));
        figures.save_png("06_tinyrenderer_triangles", tri::magnified(tinyrenderer_triangles(), 3));
        figures.save_png("06_barycentric_weights", tri::magnified(weights(), 3));
        figures.save_png("06_zero_area_unguarded", tri::magnified(zero_area_unguarded(), 24));
        figures.save_png("06_float_vs_double", tri::magnified(float_versus_double(), 24));
        figures.save_png("06_float_zero_area_far_away",
                         tri::magnified(float_zero_area_far_away(), 12));
      });
}
