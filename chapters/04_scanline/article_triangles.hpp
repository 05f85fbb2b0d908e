/// @file
/// The article's three test triangles on its 200×200 image, shared by the figures and the tests.
#pragma once

#include <array>

#include <glm/vec2.hpp>

#include "common/color.hpp"

namespace tri::ch04 {

/// Side of the article's square test image.
inline constexpr int article_image_size = 200;

/// One test triangle: its vertices in the order the article passes them, and its colour.
struct ArticleTriangle {
  std::array<glm::ivec2, 3> vertices;
  Color color;
};

// [listing article_triangles]
/// Red, white and green, as the article draws them.
inline constexpr std::array<ArticleTriangle, 3> article_triangles{{
    {{{{10, 70}, {50, 160}, {70, 80}}}, colors::red},
    {{{{180, 50}, {150, 1}, {70, 180}}}, colors::white},
    {{{{180, 150}, {120, 160}, {130, 180}}}, colors::green},
}};
// [/listing]

}  // namespace tri::ch04
