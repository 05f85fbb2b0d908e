#include "chapters/05_edge_function/point_in_triangle.hpp"

#include "chapters/05_edge_function/cross_product.hpp"

namespace tri::ch05 {

// [listing inside_test]
bool same_sign_or_zero(glm::i64vec3 edge_values) noexcept {
  const glm::i64vec3& e = edge_values;
  return (e.x >= 0 && e.y >= 0 && e.z >= 0) || (e.x <= 0 && e.y <= 0 && e.z <= 0);
}

bool inside_triangle(glm::ivec2 a, glm::ivec2 b, glm::ivec2 c, glm::ivec2 p) noexcept {
  return same_sign_or_zero(edge_crosses(a, b, c, p));
}
// [/listing]

bool inside_triangle_published_bug(glm::ivec2 a, glm::ivec2 b, glm::ivec2 c,
                                   glm::ivec2 p) noexcept {
  return same_sign_or_zero(edge_crosses_published_bug(a, b, c, p));
}

}  // namespace tri::ch05
