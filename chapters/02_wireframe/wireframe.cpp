#include "wireframe.hpp"

#include "lines.hpp"

namespace tri::ch02 {

// [listing draw_wireframe_triangle]
void draw_wireframe_triangle(Canvas& canvas, glm::ivec2 p0, glm::ivec2 p1, glm::ivec2 p2,
                             Color color) {
  ch01::draw_line_gambetta(canvas, p0, p1, color);
  ch01::draw_line_gambetta(canvas, p1, p2, color);
  ch01::draw_line_gambetta(canvas, p2, p0, color);
}
// [/listing]

}  // namespace tri::ch02
