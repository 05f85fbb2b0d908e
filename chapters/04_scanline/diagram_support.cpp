#include "chapters/04_scanline/diagram_support.hpp"

#include <algorithm>
#include <array>
#include <utility>

#include <cstdint>

#include "chapters/04_scanline/boundaries.hpp"

namespace tri::ch04::figures {

Canvas drawn_by(const Step& step, const ch02::TinyrendererTriangle& triangle) {
  Canvas canvas(ch02::tinyrenderer_image_size, ch02::tinyrenderer_image_size);
  canvas.enable_write_counts();
  step(canvas, triangle.vertices[0], triangle.vertices[1], triangle.vertices[2]);
  return canvas;
}

const ch02::TinyrendererTriangle& diagram_triangle() noexcept {
  return ch02::tinyrenderer_triangles[2];
}

PixelDiagram green_diagram(std::string title) {
  PixelDiagram diagram({118, 148}, {182, 182}, std::move(title), 12);
  const auto [a, b, c] = diagram_triangle().vertices;
  diagram.triangle(a, b, c, diagram_colors::black, 1.25);
  const SortedTriangle t = sort_by_y(a, b, c);
  diagram.vertex(t.p0, "t0", LabelPlace::below_left);
  diagram.vertex(t.p1, "t1", LabelPlace::below_right);
  diagram.vertex(t.p2, "t2", LabelPlace::above_right);
  return diagram;
}

}  // namespace tri::ch04::figures
