#include "chapters/05_edge_function/edge_function_fill.hpp"

#include "chapters/05_edge_function/bounding_box.hpp"
#include "chapters/05_edge_function/point_in_triangle.hpp"

namespace tri::ch05 {
namespace {

// [listing fill_box_by_edge_test]
// One loop for both tests, so the figure compares only the tests. A template, not a function
// pointer, so the test is inlined into the loop.
template <bool (*inside)(glm::ivec2, glm::ivec2, glm::ivec2, glm::ivec2) noexcept>
void fill_box_by_edge_test(Canvas& canvas, glm::ivec2 a, glm::ivec2 b, glm::ivec2 c, Color color) {
  const PixelBox box = bounding_box_on_canvas(a, b, c, canvas.width(), canvas.height());
  // <= on both ends: the box is inclusive, and max is at most width-1 / height-1, so ++ is safe.
  for (int y = box.min.y; y <= box.max.y; ++y) {
    for (int x = box.min.x; x <= box.max.x; ++x) {
      if (inside(a, b, c, {x, y})) canvas.put_pixel(x, y, color);
    }
  }
}
// [/listing]

}  // namespace

// [listing fill_triangle_edge_function]
void fill_triangle_edge_function(Canvas& canvas, glm::ivec2 a, glm::ivec2 b, glm::ivec2 c,
                                 Color color) {
  fill_box_by_edge_test<inside_triangle>(canvas, a, b, c, color);
}
// [/listing]

void fill_triangle_published_bug(Canvas& canvas, glm::ivec2 a, glm::ivec2 b, glm::ivec2 c,
                                 Color color) {
  fill_box_by_edge_test<inside_triangle_published_bug>(canvas, a, b, c, color);
}

}  // namespace tri::ch05
