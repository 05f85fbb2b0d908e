/// @file
/// For the figures: the part of a segment that lies over a rectangle of pixels, so an ideal edge
/// whose vertices are far away can be drawn across a small pixel diagram.
#pragma once

#include <array>
#include <optional>

#include <glm/vec2.hpp>

namespace tri::ch05 {

/// The part of segment a-b inside the squares of pixels first..last (the rectangle
/// [first - 1/2, last + 1/2] on both axes), as its two ends in the order a to b; empty when the
/// segment misses the rectangle. Liang–Barsky clipping: one parameter range cut by four sides.
std::optional<std::array<glm::dvec2, 2>> clip_segment_to_pixels(glm::dvec2 a, glm::dvec2 b,
                                                                glm::ivec2 first,
                                                                glm::ivec2 last) noexcept;

}  // namespace tri::ch05
