// Chapter 04's figures: the article's three test triangles on its 200x200 image after each step
// of the scanline fill, a map of where the two-loop and single-loop fills part ways, and a
// close-up of the pixels the int casts add.
#include <algorithm>
#include <functional>

#include "article_triangles.hpp"
#include "figures.hpp"
#include "lower_half.hpp"
#include "outline_steps.hpp"
#include "scanline_fills.hpp"

namespace {

using tri::Canvas;
using tri::Color;
using tri::ch04::article_image_size;
using tri::ch04::article_triangles;

constexpr int magnification = 4;

using TriangleStep = std::function<void(Canvas&, const tri::ch04::ArticleTriangle&)>;

// One step applied to the three test triangles in the article's order (red, white, green).
Canvas article_image(const TriangleStep& step) {
  Canvas canvas(article_image_size, article_image_size);
  for (const auto& triangle : article_triangles) step(canvas, triangle);
  return canvas;
}

// A fill step drawn in each triangle's own colour.
TriangleStep in_own_colour(void (*fill)(Canvas&, glm::ivec2, glm::ivec2, glm::ivec2, Color)) {
  return [fill](Canvas& canvas, const tri::ch04::ArticleTriangle& t) {
    fill(canvas, t.vertices[0], t.vertices[1], t.vertices[2], t.color);
  };
}

// Which fill drew each pixel: both (grey), only the two loops (red), only the single loop (cyan);
// yellow marks the rows the published single loop never reaches (row t2.y).
Canvas loop_differences() {
  Canvas canvas(article_image_size, article_image_size);
  for (const auto& t : article_triangles) {
    const auto [a, b, c] = t.vertices;
    Canvas two(article_image_size, article_image_size), one(two), published(two);
    for (Canvas* drawn : {&two, &one, &published}) drawn->enable_write_counts();
    tri::ch04::fill_two_loops(two, a, b, c, tri::colors::white);
    tri::ch04::fill_single_loop(one, a, b, c, tri::colors::white);
    tri::ch04::fill_single_loop_as_published(published, a, b, c, tri::colors::white);
    for (int y = 0; y < canvas.height(); ++y) {
      for (int x = 0; x < canvas.width(); ++x) {
        const bool in_two = two.write_count(x, y) > 0, in_one = one.write_count(x, y) > 0;
        if (in_one && published.write_count(x, y) == 0) {
          canvas.put_pixel(x, y, tri::colors::yellow);
        } else if (in_two && in_one) {
          canvas.put_pixel(x, y, tri::colors::gray);
        } else if (in_two) {
          canvas.put_pixel(x, y, tri::colors::red);
        } else if (in_one) {
          canvas.put_pixel(x, y, tri::colors::cyan);
        }
      }
    }
  }
  return canvas;
}

// The red triangle's lower-left corner: white where the single loop draws a pixel whose centre
// lies in the triangle, red where it draws one outside (the int casts), dark where it draws none.
Canvas truncation_close_up() {
  constexpr int left = 8, bottom = 68, width = 40, height = 16;
  const auto [a, b, c] = article_triangles[0].vertices;
  Canvas drawn(article_image_size, article_image_size);
  drawn.enable_write_counts();
  tri::ch04::fill_single_loop(drawn, a, b, c, tri::colors::white);
  // Twice the signed area of (p, q, (x, y)): the side of edge pq the pixel centre is on.
  const auto side = [](glm::ivec2 p, glm::ivec2 q, int x, int y) {
    return (q.x - p.x) * (y - p.y) - (q.y - p.y) * (x - p.x);
  };
  const int winding = side(a, b, c.x, c.y) > 0 ? 1 : -1;
  Canvas close_up(width, height, Color{40, 40, 40, 255});
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const int px = left + x, py = bottom + y;
      if (drawn.write_count(px, py) == 0) continue;
      const bool inside = winding * side(a, b, px, py) >= 0 && winding * side(b, c, px, py) >= 0 &&
                          winding * side(c, a, px, py) >= 0;
      close_up.put_pixel(x, y, inside ? tri::colors::white : tri::colors::red);
    }
  }
  return close_up;
}

}  // namespace

int main(int argc, char** argv) {
  return tri::run_chapter_program(
      argc, argv, "04_scanline",
      "Chapter 04, scanline fill (tinyrenderer lesson 2): the article's three test triangles on\n"
      "its 200x200 image after each step, magnified 4x: 04_outlines, 04_sorted_boundaries,\n"
      "04_lower_half_points, 04_lower_half_filled, 04_two_loops, 04_single_loop; then\n"
      "04_loop_differences (two loops against the single loop) and 04_truncation_close_up\n"
      "(pixels the int casts add to the red triangle, magnified 16x).",
      [](tri::FigureWriter& figures) {
        const auto save = [&](const char* name, const Canvas& canvas) {
          figures.save_png(name, tri::magnified(canvas, magnification));
        };
        save("04_outlines", article_image([](Canvas& canvas, const auto& t) {
               tri::ch04::draw_outline(canvas, t.vertices[0], t.vertices[1], t.vertices[2],
                                       t.color);
             }));
        save("04_sorted_boundaries", article_image([](Canvas& canvas, const auto& t) {
               tri::ch04::draw_sorted_boundaries(canvas, t.vertices[0], t.vertices[1],
                                                 t.vertices[2]);
             }));
        save("04_lower_half_points", article_image([](Canvas& canvas, const auto& t) {
               tri::ch04::draw_lower_half_boundary_points(canvas, t.vertices[0], t.vertices[1],
                                                          t.vertices[2]);
             }));
        save("04_lower_half_filled", article_image(in_own_colour(tri::ch04::fill_lower_half)));
        save("04_two_loops", article_image(in_own_colour(tri::ch04::fill_two_loops)));
        save("04_single_loop", article_image(in_own_colour(tri::ch04::fill_single_loop)));
        save("04_loop_differences", loop_differences());
        figures.save_png("04_truncation_close_up", tri::magnified(truncation_close_up(), 16));
      });
}
