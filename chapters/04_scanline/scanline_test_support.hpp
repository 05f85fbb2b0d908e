/// @file
/// What chapter 04's tests share: drawing one step into a counting canvas and reading back its
/// pixels, and whole rows of pixels.
#pragma once

#include <glm/vec2.hpp>

#include "common/canvas.hpp"
#include "tests/support/pixels.hpp"

namespace tri::ch04::testing {

using tri::testing::minus;
using tri::testing::PixelSet;
using tri::testing::vertex_orders;

/// The signature of the chapter's fill steps.
using FillStep = void (*)(Canvas&, glm::ivec2, glm::ivec2, glm::ivec2, Color);

/// A canvas that counts writes, with the step drawn on it in white.
inline Canvas drawn_by(FillStep step, glm::ivec2 a, glm::ivec2 b, glm::ivec2 c, int width = 200,
                       int height = 200) {
  Canvas canvas(width, height);
  canvas.enable_write_counts();
  step(canvas, a, b, c, colors::white);
  return canvas;
}

/// The pixels a fill step writes.
inline PixelSet pixels_of(FillStep step, glm::ivec2 a, glm::ivec2 b, glm::ivec2 c, int width = 200,
                          int height = 200) {
  return tri::testing::written_pixels(drawn_by(step, a, b, c, width, height));
}

/// Every pixel of row y from x_first to x_last, both included.
inline void add_row(PixelSet& set, int y, int x_first, int x_last) {
  for (int x = x_first; x <= x_last; ++x) set.emplace(x, y);
}

}  // namespace tri::ch04::testing
