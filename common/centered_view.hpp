/// @file
/// Gambetta's centred coordinates on top of the canvas.
#pragma once

#include <glm/vec2.hpp>

#include "common/canvas.hpp"

namespace tri {

/// *Computer Graphics from Scratch* puts the origin at the middle of the canvas, x right and y up.
/// This view maps such a point (x, y) to the canvas pixel (W/2 + x, H/2 + y); both use y up, so no
/// flip is needed.
class CenteredView {
 public:
  explicit CenteredView(const Canvas& canvas) noexcept : canvas_(canvas) {}

  /// The canvas pixel that the centred point p lands on.
  glm::ivec2 to_canvas(glm::ivec2 p) const noexcept {
    return {canvas_.width() / 2 + p.x, canvas_.height() / 2 + p.y};
  }

 private:
  const Canvas& canvas_;
};

}  // namespace tri
