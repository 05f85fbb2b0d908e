#include "chapters/02_wireframe/wireframe.hpp"

#include <algorithm>
#include <stdexcept>

#include "chapters/01_lines/lines.hpp"

namespace tri::ch02 {

// [listing draw_wireframe_triangle]
void draw_wireframe_triangle(Canvas& canvas, glm::ivec2 p0, glm::ivec2 p1, glm::ivec2 p2,
                             Color color) {
  ch01::draw_line_gambetta(canvas, p0, p1, color);
  ch01::draw_line_gambetta(canvas, p1, p2, color);
  ch01::draw_line_gambetta(canvas, p2, p0, color);
}
// [/listing]

std::array<std::vector<glm::ivec2>, 3> outline_edge_pixels(glm::ivec2 p0, glm::ivec2 p1,
                                                           glm::ivec2 p2) {
  constexpr int limit = 4096;
  for (const glm::ivec2 p : {p0, p1, p2}) {
    if (p.x < 0 || p.y < 0 || p.x >= limit || p.y >= limit) {
      throw std::invalid_argument("outline_edge_pixels takes coordinates in 0..4095");
    }
  }
  const int width = std::max({p0.x, p1.x, p2.x}) + 1;
  const int height = std::max({p0.y, p1.y, p2.y}) + 1;
  const std::array<std::array<glm::ivec2, 2>, 3> edges{{{p0, p1}, {p1, p2}, {p2, p0}}};
  std::array<std::vector<glm::ivec2>, 3> pixels;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    Canvas canvas(width, height);
    canvas.enable_write_counts();
    ch01::draw_line_gambetta(canvas, edges[i][0], edges[i][1], colors::white);
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        if (canvas.write_count(x, y) > 0) pixels[i].emplace_back(x, y);
      }
    }
  }
  return pixels;
}

}  // namespace tri::ch02
