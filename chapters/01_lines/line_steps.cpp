#include "chapters/01_lines/line_steps.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <stdexcept>
#include <utility>

#include "common/canvas.hpp"
#include "common/color.hpp"

namespace tri::ch01 {

std::vector<LineStep> steps_against_exact(DrawLineFunction draw, glm::ivec2 from, glm::ivec2 to) {
  constexpr int limit = 4096;
  for (const glm::ivec2 p : {from, to}) {
    if (p.x < 0 || p.y < 0 || p.x >= limit || p.y >= limit) {
      throw std::invalid_argument("steps_against_exact takes coordinates in 0..4095");
    }
  }
  Canvas canvas(std::max(from.x, to.x) + 1, std::max(from.y, to.y) + 1);
  canvas.enable_write_counts();
  draw(canvas, from, to, colors::white);

  const bool x_major = std::abs(to.x - from.x) >= std::abs(to.y - from.y);
  const int minor_end = x_major ? canvas.height() : canvas.width();
  std::vector<LineStep> steps;
  for (const ExactLinePixel& exact : exact_line_pixels(from, to)) {
    const int major = x_major ? exact.pixel.x : exact.pixel.y;
    bool found = false;
    for (int minor = 0; minor < minor_end && !found; ++minor) {
      const glm::ivec2 p = x_major ? glm::ivec2(major, minor) : glm::ivec2(minor, major);
      if (canvas.write_count(p.x, p.y) > 0) {
        steps.push_back({exact, p});
        found = true;
      }
    }
    if (!found) throw std::logic_error("the line algorithm drew no pixel at one step");
  }
  return steps;
}

std::vector<Segment> star_spokes(glm::ivec2 centre, int radius, int count) {
  std::vector<Segment> spokes;
  for (int i = 0; i < count; ++i) {
    const double angle = 2 * std::numbers::pi * i / count;
    const glm::ivec2 tip(centre.x + static_cast<int>(std::lround(radius * std::cos(angle))),
                         centre.y + static_cast<int>(std::lround(radius * std::sin(angle))));
    spokes.push_back({centre, tip});
  }
  return spokes;
}

}  // namespace tri::ch01
