/// @file
/// The exact answer the line algorithms approximate: for every step along the major axis, the
/// pixel nearest to the true segment, computed with integers only.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

namespace tri::ch01 {

/// One pixel of the exact line.
struct ExactLinePixel {
  glm::ivec2 pixel;  ///< the nearest pixel; a tie rounds the minor coordinate up
  bool tie;          ///< the true line passes exactly halfway between two pixels here
};

/// The exact pixel of the segment p0-p1 at one major coordinate (x when |dx| >= |dy|, else y),
/// which must lie between the endpoints' major coordinates.
ExactLinePixel exact_line_pixel_at(glm::ivec2 p0, glm::ivec2 p1, std::int64_t major);

/// The pixels of the segment p0-p1, one per integer step of its major axis (x when
/// |dx| >= |dy|), ordered from the endpoint with the smaller major coordinate. The minor
/// coordinate at step k is m0 + dm * k / n exactly; it is rounded to nearest with ties flagged,
/// since that is where correct algorithms may disagree. Coordinates within ±2^30.
std::vector<ExactLinePixel> exact_line_pixels(glm::ivec2 p0, glm::ivec2 p1);

}  // namespace tri::ch01
