/// @file
/// Colours: one RGBA8 value per pixel, as the canvas stores them.
#pragma once

#include <glm/ext/vector_uint4_sized.hpp>

namespace tri {

/// An RGBA colour, 8 bits per channel.
using Color = glm::u8vec4;

/// The handful of named colours the figures use.
namespace colors {
inline constexpr Color black{0, 0, 0, 255};
inline constexpr Color white{255, 255, 255, 255};
inline constexpr Color red{255, 0, 0, 255};
inline constexpr Color green{0, 255, 0, 255};
inline constexpr Color blue{0, 0, 255, 255};
inline constexpr Color yellow{255, 255, 0, 255};
inline constexpr Color cyan{0, 255, 255, 255};
inline constexpr Color magenta{255, 0, 255, 255};
inline constexpr Color gray{128, 128, 128, 255};
}  // namespace colors

}  // namespace tri
