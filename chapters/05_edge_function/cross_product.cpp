#include "chapters/05_edge_function/cross_product.hpp"

namespace tri::ch05 {
namespace {

// b - a in 64 bits: for coordinates at ±2^30 the difference needs 32 bits, one more than int has.
glm::i64vec2 difference(glm::ivec2 b, glm::ivec2 a) noexcept {
  return glm::i64vec2(b) - glm::i64vec2(a);
}

}  // namespace

// [listing edge_crosses]
std::int64_t edge_cross(glm::ivec2 a, glm::ivec2 b, glm::ivec2 p) noexcept {
  return cross_2d(difference(b, a), difference(p, a));
}

glm::i64vec3 edge_crosses(glm::ivec2 a, glm::ivec2 b, glm::ivec2 c, glm::ivec2 p) noexcept {
  return {edge_cross(a, b, p), edge_cross(b, c, p), edge_cross(c, a, p)};
}
// [/listing]

// [listing edge_crosses_published_bug]
glm::i64vec3 edge_crosses_published_bug(glm::ivec2 a, glm::ivec2 b, glm::ivec2 c,
                                        glm::ivec2 p) noexcept {
  // The slip: BP and CP are measured from (b.x, a.y) and (c.x, a.y), not from b and c.
  const glm::ivec2 b_at_a_height(b.x, a.y);
  const glm::ivec2 c_at_a_height(c.x, a.y);
  return {edge_cross(a, b, p), cross_2d(difference(c, b), difference(p, b_at_a_height)),
          cross_2d(difference(a, c), difference(p, c_at_a_height))};
}
// [/listing]

}  // namespace tri::ch05
