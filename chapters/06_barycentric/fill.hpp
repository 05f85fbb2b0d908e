/// @file
/// Step 4: the fill. Every pixel of the bounding box is tested with its barycentric weights;
/// plus the fill the weights are really for, colouring each pixel by them.
#pragma once

#include <concepts>

#include <glm/vec2.hpp>

#include "common/canvas.hpp"
#include "common/color.hpp"

namespace tri::ch06 {

/// Fills triangle abc (integer pixel centres, either winding): every pixel of the clamped
/// bounding box whose weights, computed in Scalar, pass is_inside. Pixels on an edge are drawn;
/// a zero-area triangle draws nothing. Instantiated for float and double.
template <std::floating_point Scalar>
void fill_triangle_barycentric(Canvas& canvas, glm::ivec2 a, glm::ivec2 b, glm::ivec2 c,
                               Color color) noexcept;

/// The same fill with barycentric_unguarded: what the article's loop would draw without the
/// zero-area guard (NaN weights pass the inside test). For tests and figures only, never
/// registered. Instantiated for float and double.
template <std::floating_point Scalar>
void fill_triangle_barycentric_unguarded(Canvas& canvas, glm::ivec2 a, glm::ivec2 b, glm::ivec2 c,
                                         Color color) noexcept;

/// Fills the same pixels as fill_triangle_barycentric<double>, each coloured by the blend
/// wA·color_a + wB·color_b + wC·color_c of the vertex colours, so each vertex pixel shows its own
/// colour and the colours fade linearly across the triangle.
void fill_triangle_with_weights(Canvas& canvas, glm::ivec2 a, glm::ivec2 b, glm::ivec2 c,
                                Color color_a, Color color_b, Color color_c) noexcept;

extern template void fill_triangle_barycentric<float>(Canvas&, glm::ivec2, glm::ivec2, glm::ivec2,
                                                      Color) noexcept;
extern template void fill_triangle_barycentric<double>(Canvas&, glm::ivec2, glm::ivec2, glm::ivec2,
                                                       Color) noexcept;
extern template void fill_triangle_barycentric_unguarded<float>(Canvas&, glm::ivec2, glm::ivec2,
                                                                glm::ivec2, Color) noexcept;
extern template void fill_triangle_barycentric_unguarded<double>(Canvas&, glm::ivec2, glm::ivec2,
                                                                 glm::ivec2, Color) noexcept;

}  // namespace tri::ch06
