// Chapter 02's figures: Gambetta's Figure 7-1, tinyrenderer's three test triangles as outlines,
// and a close-up where the three lines meet.
#include <array>

#include "centered_view.hpp"
#include "figures.hpp"
#include "wireframe.hpp"

namespace {

using tri::Canvas;

// Figure 7-1: (-200,-250), (200,50), (20,250) in Gambetta's centred coordinates.
Canvas gambetta_figure_7_1() {
  Canvas canvas(600, 600, tri::colors::white);
  tri::CenteredView view(canvas);
  tri::ch02::draw_wireframe_triangle(canvas, view.to_canvas({-200, -250}),
                                     view.to_canvas({200, 50}), view.to_canvas({20, 250}),
                                     tri::colors::black);
  return canvas;
}

// tinyrenderer lesson 2's test triangles on its 200x200 image, in its colours.
Canvas tinyrenderer_triangles() {
  Canvas canvas(200, 200);
  const std::array<std::array<glm::ivec2, 3>, 3> triangles{{
      {{{10, 70}, {50, 160}, {70, 80}}},
      {{{180, 50}, {150, 1}, {70, 180}}},
      {{{180, 150}, {120, 160}, {130, 180}}},
  }};
  const std::array<tri::Color, 3> colors{tri::colors::red, tri::colors::white, tri::colors::green};
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    const auto& t = triangles[i];
    tri::ch02::draw_wireframe_triangle(canvas, t[0], t[1], t[2], colors[i]);
  }
  return canvas;
}

// A small triangle pixel by pixel: white where one edge drew, yellow where two edges met.
Canvas joints_close_up() {
  Canvas counted(9, 8);
  counted.enable_write_counts();
  tri::ch02::draw_wireframe_triangle(counted, {1, 1}, {7, 3}, {3, 6}, tri::colors::white);
  Canvas canvas(counted.width(), counted.height(), tri::Color{40, 40, 40, 255});
  for (int y = 0; y < canvas.height(); ++y) {
    for (int x = 0; x < canvas.width(); ++x) {
      const auto count = counted.write_count(x, y);
      if (count > 0) canvas.put_pixel(x, y, count > 1 ? tri::colors::yellow : tri::colors::white);
    }
  }
  return canvas;
}

}  // namespace

int main(int argc, char** argv) {
  return tri::run_chapter_program(
      argc, argv, "02_wireframe",
      "Chapter 02, wireframe triangles: Gambetta's Figure 7-1 on a centred 600x600 canvas\n"
      "(02_wireframe_figure_7_1.png), tinyrenderer's three test triangles outlined on a 200x200\n"
      "image, magnified 4x (02_wireframe_tinyrenderer.png), and a close-up of where the three\n"
      "lines meet (02_wireframe_joints.png).",
      [](tri::FigureWriter& figures) {
        figures.save_png("02_wireframe_figure_7_1", gambetta_figure_7_1());
        figures.save_png("02_wireframe_tinyrenderer", tri::magnified(tinyrenderer_triangles(), 4));
        figures.save_png("02_wireframe_joints", tri::magnified(joints_close_up(), 32));
      });
}
