// Chapter 05's figures: the tinyrenderer triangles filled by the edge-function test, the signs of
// the three edge values, the bounding box (and its clamping), the published bug, zero-area cases.
#include <array>

#include "bounding_box.hpp"
#include "cross_product.hpp"
#include "edge_function_fill.hpp"
#include "figures.hpp"
#include "lines.hpp"

namespace {

using tri::Canvas;
using tri::Color;
using Vertices = std::array<glm::ivec2, 3>;

constexpr Color dim_blue{40, 50, 110, 255};
constexpr Color dark_gray{70, 70, 70, 255};

// tinyrenderer lesson 2's three test triangles on its 200x200 image, in its colours.
constexpr std::array<Vertices, 3> tinyrenderer_triangles{{
    {{{10, 70}, {50, 160}, {70, 80}}},
    {{{180, 50}, {150, 1}, {70, 180}}},
    {{{180, 150}, {120, 160}, {130, 180}}},
}};
constexpr std::array<Color, 3> tinyrenderer_colors{tri::colors::red, tri::colors::white,
                                                   tri::colors::green};

Canvas tinyrenderer_fill() {
  Canvas canvas(200, 200);
  for (std::size_t i = 0; i < tinyrenderer_triangles.size(); ++i) {
    const auto& [a, b, c] = tinyrenderer_triangles[i];
    tri::ch05::fill_triangle_edge_function(canvas, a, b, c, tinyrenderer_colors[i]);
  }
  return canvas;
}

// Each pixel gets red when AB x AP >= 0, green when BC x BP >= 0, blue when CA x CP >= 0: the
// triangle is where all three mix to white.
Canvas edge_signs() {
  Canvas canvas(48, 40);
  const glm::ivec2 a(8, 6), b(40, 14), c(18, 34);
  for (int y = 0; y < canvas.height(); ++y) {
    for (int x = 0; x < canvas.width(); ++x) {
      const glm::i64vec3 e = tri::ch05::edge_crosses(a, b, c, {x, y});
      const auto on = [](std::int64_t value) {
        return static_cast<std::uint8_t>(value >= 0 ? 255 : 0);
      };
      canvas.put_pixel(x, y, Color{on(e.x), on(e.y), on(e.z), 255});
    }
  }
  return canvas;
}

// Blue: the pixels of the clamped bounding box the loop tests; white: those inside; red: the
// vertices that are on the canvas.
Canvas bounding_box_figure(int width, int height, const Vertices& v) {
  Canvas canvas(width, height);
  const auto box = tri::ch05::bounding_box_on_canvas(v[0], v[1], v[2], width, height);
  for (int y = box.min.y; y <= box.max.y; ++y) {
    for (int x = box.min.x; x <= box.max.x; ++x) canvas.put_pixel(x, y, dim_blue);
  }
  tri::ch05::fill_triangle_edge_function(canvas, v[0], v[1], v[2], tri::colors::white);
  for (const glm::ivec2 vertex : v) {
    if (canvas.contains(vertex)) canvas.put_pixel(vertex, tri::colors::red);
  }
  return canvas;
}

// White: drawn by both tests; blue: inside, but lost by the published test; red: drawn only by
// the published test.
Canvas published_bug_comparison() {
  Canvas correct(200, 200), published(200, 200), comparison(200, 200);
  for (const auto& [a, b, c] : tinyrenderer_triangles) {
    tri::ch05::fill_triangle_edge_function(correct, a, b, c, tri::colors::white);
    tri::ch05::fill_triangle_published_bug(published, a, b, c, tri::colors::white);
  }
  for (int y = 0; y < 200; ++y) {
    for (int x = 0; x < 200; ++x) {
      const bool in_correct = correct.pixel(x, y) == tri::colors::white;
      const bool in_published = published.pixel(x, y) == tri::colors::white;
      if (in_correct && in_published) comparison.put_pixel(x, y, tri::colors::white);
      if (in_correct && !in_published) comparison.put_pixel(x, y, dim_blue);
      if (!in_correct && in_published) comparison.put_pixel(x, y, tri::colors::red);
    }
  }
  return comparison;
}

// Zero-area triangles: grey is the segment as chapter 01's Bresenham draws it, white what the
// fill draws, only the pixel centres exactly on the segment.
Canvas zero_area() {
  Canvas canvas(24, 30);
  const std::array<Vertices, 3> segments{{
      {{{0, 0}, {10, 10}, {20, 20}}},
      {{{2, 22}, {12, 25}, {22, 28}}},
      {{{20, 4}, {20, 4}, {20, 4}}},
  }};
  for (const auto& [a, b, c] : segments) {
    tri::ch01::draw_line_bresenham(canvas, a, c, dark_gray);
    tri::ch05::fill_triangle_edge_function(canvas, a, b, c, tri::colors::white);
  }
  return canvas;
}

}  // namespace

int main(int argc, char** argv) {
  return tri::run_chapter_program(
      argc, argv, "05_edge_function",
      "Chapter 05, the edge-function fill: tinyrenderer's three triangles\n"
      "(05_tinyrenderer_triangles.png), the signs of the three edge cross products\n"
      "(05_edge_signs.png), the bounding box and its clamping to the canvas\n"
      "(05_bounding_box.png, 05_bounding_box_clamped.png), the published points[0].y bug against\n"
      "the correct test (05_published_bug.png) and zero-area triangles (05_zero_area.png).",
      [](tri::FigureWriter& figures) {
        figures.save_png("05_tinyrenderer_triangles", tri::magnified(tinyrenderer_fill(), 3));
        figures.save_png("05_edge_signs", tri::magnified(edge_signs(), 12));
        figures.save_png(
            "05_bounding_box",
            tri::magnified(bounding_box_figure(40, 32, {{{5, 4}, {34, 11}, {14, 27}}}), 12));
        figures.save_png(
            "05_bounding_box_clamped",
            tri::magnified(bounding_box_figure(40, 32, {{{-12, 6}, {24, -9}, {30, 26}}}), 12));
        figures.save_png("05_published_bug", tri::magnified(published_bug_comparison(), 3));
        figures.save_png("05_zero_area", tri::magnified(zero_area(), 16));
      });
}
