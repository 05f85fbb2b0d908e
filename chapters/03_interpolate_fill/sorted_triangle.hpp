/// @file
/// A triangle's vertices sorted by height, as step 1 of the fill leaves them (chapter 04's
/// scanline fill sorts into the same type).
#pragma once

#include <glm/vec2.hpp>

namespace tri::ch03 {

/// The vertices sorted by y: p0.y <= p1.y <= p2.y.
struct SortedTriangle {
  glm::ivec2 p0;  ///< lowest vertex
  glm::ivec2 p1;  ///< middle vertex
  glm::ivec2 p2;  ///< highest vertex
};

}  // namespace tri::ch03
