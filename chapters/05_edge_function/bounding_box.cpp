#include "chapters/05_edge_function/bounding_box.hpp"

#include <algorithm>

namespace tri::ch05 {

// [listing bounding_box_on_canvas]
PixelBox bounding_box_on_canvas(glm::ivec2 a, glm::ivec2 b, glm::ivec2 c, int width, int height) {
  // Clamp each end on one side only: a box left of the canvas keeps max.x < 0 and stays empty.
  return {{std::max(0, std::min({a.x, b.x, c.x})), std::max(0, std::min({a.y, b.y, c.y}))},
          {std::min(width - 1, std::max({a.x, b.x, c.x})),
           std::min(height - 1, std::max({a.y, b.y, c.y}))}};
}
// [/listing]

}  // namespace tri::ch05
