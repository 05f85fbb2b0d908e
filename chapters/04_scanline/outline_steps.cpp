#include "chapters/04_scanline/outline_steps.hpp"

#include "chapters/01_lines/lines.hpp"
#include "chapters/04_scanline/boundaries.hpp"
#include "common/pixel_diagram.hpp"

namespace tri::ch04 {

// [listing draw_outline]
void draw_outline(Canvas& canvas, glm::ivec2 a, glm::ivec2 b, glm::ivec2 c, Color color) {
  ch01::draw_line_bresenham(canvas, a, b, color);
  ch01::draw_line_bresenham(canvas, b, c, color);
  ch01::draw_line_bresenham(canvas, c, a, color);
}
// [/listing]

// [listing draw_sorted_boundaries]
void draw_sorted_boundaries(Canvas& canvas, glm::ivec2 a, glm::ivec2 b, glm::ivec2 c) {
  const auto [t0, t1, t2] = sort_by_y(a, b, c);
  ch01::draw_line_bresenham(canvas, t0, t1, diagram_colors::blue);
  ch01::draw_line_bresenham(canvas, t1, t2, diagram_colors::blue);
  // Last, so the long boundary stays vermillion where it meets B at t0 and t2.
  ch01::draw_line_bresenham(canvas, t2, t0, diagram_colors::vermillion);
}
// [/listing]

}  // namespace tri::ch04
