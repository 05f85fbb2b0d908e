#include "tests/support/pixels.hpp"

#include <algorithm>
#include <iterator>
#include <stdexcept>

namespace tri::testing {
namespace {

PixelSet pixels_with_count_above(const Canvas& canvas, std::uint32_t threshold) {
  if (!canvas.write_counts_enabled()) throw std::logic_error("enable write counts first");
  PixelSet set;
  for (int y = 0; y < canvas.height(); ++y) {
    for (int x = 0; x < canvas.width(); ++x) {
      if (canvas.write_count(x, y) > threshold) set.emplace(x, y);
    }
  }
  return set;
}

}  // namespace

PixelSet written_pixels(const Canvas& canvas) {
  return pixels_with_count_above(canvas, 0);
}
PixelSet overdrawn_pixels(const Canvas& canvas) {
  return pixels_with_count_above(canvas, 1);
}

PixelSet minus(const PixelSet& from, const PixelSet& without) {
  PixelSet rest;
  std::set_difference(from.begin(), from.end(), without.begin(), without.end(),
                      std::inserter(rest, rest.end()));
  return rest;
}

PixelSet intersection(const PixelSet& a, const PixelSet& b) {
  PixelSet both;
  std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::inserter(both, both.end()));
  return both;
}

PixelSet united(const PixelSet& a, const PixelSet& b) {
  PixelSet all = a;
  all.insert(b.begin(), b.end());
  return all;
}

PixelSet symmetric_difference(const PixelSet& a, const PixelSet& b) {
  PixelSet either;
  std::set_symmetric_difference(a.begin(), a.end(), b.begin(), b.end(),
                                std::inserter(either, either.end()));
  return either;
}

std::array<VertexTriple, 6> vertex_orders(glm::ivec2 a, glm::ivec2 b, glm::ivec2 c) {
  return vertex_orders(VertexTriple{a, b, c});
}

std::int64_t doubled_area(glm::ivec2 a, glm::ivec2 b, glm::ivec2 c) {
  return (static_cast<std::int64_t>(b.x) - a.x) * (static_cast<std::int64_t>(c.y) - a.y) -
         (static_cast<std::int64_t>(c.x) - a.x) * (static_cast<std::int64_t>(b.y) - a.y);
}

PixelSet inclusive_pixels(glm::ivec2 a, glm::ivec2 b, glm::ivec2 c, int width, int height) {
  // Twice the signed area of (p, q, r): > 0 when r is left of p -> q.
  const auto cross = [](glm::ivec2 p, glm::ivec2 q, std::int64_t rx, std::int64_t ry) {
    return (static_cast<std::int64_t>(q.x) - p.x) * (ry - p.y) -
           (static_cast<std::int64_t>(q.y) - p.y) * (rx - p.x);
  };
  const std::int64_t area = cross(a, b, c.x, c.y);
  PixelSet set;
  if (area == 0) return set;
  const std::int64_t sign = area > 0 ? 1 : -1;
  const int x0 = std::max(0, std::min({a.x, b.x, c.x})),
            x1 = std::min(width - 1, std::max({a.x, b.x, c.x}));
  const int y0 = std::max(0, std::min({a.y, b.y, c.y})),
            y1 = std::min(height - 1, std::max({a.y, b.y, c.y}));
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      if (sign * cross(a, b, x, y) >= 0 && sign * cross(b, c, x, y) >= 0 &&
          sign * cross(c, a, x, y) >= 0) {
        set.emplace(x, y);
      }
    }
  }
  return set;
}

glm::ivec2 random_point(Random& random, int low, int high) {
  const int x = random.integer(low, high);
  const int y = random.integer(low, high);
  return {x, y};
}

VertexTriple random_vertices(Random& random, int low, int high) {
  const glm::ivec2 a = random_point(random, low, high);
  const glm::ivec2 b = random_point(random, low, high);
  const glm::ivec2 c = random_point(random, low, high);
  return {a, b, c};
}

glm::dvec2 random_real_point(Random& random, double low, double high) {
  const double x = random.real(low, high);
  const double y = random.real(low, high);
  return {x, y};
}

std::array<glm::dvec2, 3> random_real_triangle(Random& random, double low, double high) {
  const glm::dvec2 a = random_real_point(random, low, high);
  const glm::dvec2 b = random_real_point(random, low, high);
  const glm::dvec2 c = random_real_point(random, low, high);
  return {a, b, c};
}

}  // namespace tri::testing
