#include "chapters/03_interpolate_fill/diagram_support.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <string_view>
#include <utility>

namespace tri::ch03::figures {

std::string short_number(double value) {
  std::array<char, 32> buffer{};
  std::snprintf(buffer.data(), buffer.size(), "%.2f", value);
  std::string text(buffer.data());
  while (text.back() == '0') text.pop_back();
  if (text.back() == '.') text.pop_back();
  return text == "-0" ? "0" : text;
}

bool centre_in_triangle(glm::ivec2 a, glm::ivec2 b, glm::ivec2 c, glm::ivec2 pixel) noexcept {
  // Twice the signed area of (p, q, pixel): which side of the edge p q the centre is on.
  const auto side = [pixel](glm::ivec2 p, glm::ivec2 q) {
    return (std::int64_t{q.x} - p.x) * (std::int64_t{pixel.y} - p.y) -
           (std::int64_t{q.y} - p.y) * (std::int64_t{pixel.x} - p.x);
  };
  const std::int64_t ab = side(a, b), bc = side(b, c), ca = side(c, a);
  return (ab >= 0 && bc >= 0 && ca >= 0) || (ab <= 0 && bc <= 0 && ca <= 0);
}

bool halfway_tie(glm::ivec2 a, glm::ivec2 b, int x, glm::ivec2& pixel) noexcept {
  if (b.x < a.x) std::swap(a, b);  // the same line, with a positive run
  const std::int64_t dx = b.x - a.x, num = std::int64_t{x - a.x} * (b.y - a.y);
  std::int64_t whole = num / dx, rest = num % dx;
  if (rest < 0) {  // floor division: rest in [0, dx)
    rest += dx;
    --whole;
  }
  if (2 * rest != dx) return false;
  pixel = {x, static_cast<int>(a.y + whole + 1)};
  return true;
}

PixelDiagram hand_diagram(std::string title, bool edges) {
  PixelDiagram diagram({-1, -1}, {8, 6}, std::move(title), 48);
  const auto [p0, p1, p2] = hand_triangle;
  if (edges) diagram.triangle(p0, p1, p2, diagram_colors::dark_gray, 1.5);
  diagram.vertex(p0, "P0", LabelPlace::below_right);
  diagram.vertex(p1, "P1", LabelPlace::below_right);
  diagram.vertex(p2, "P2", LabelPlace::above_right);
  return diagram;
}

}  // namespace tri::ch03::figures
