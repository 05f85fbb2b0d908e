#include "chapters/09_anti_aliasing/area_oracle.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace tri::ch09 {
namespace {

constexpr std::int64_t unit = std::int64_t{1} << oracle_subpixel_bits;  // grid steps per pixel
constexpr std::int64_t half = unit / 2;
constexpr double max_pixels = 32768.0;

/// A vertex in grid units (1/256 pixel).
struct GridPoint {
  std::int64_t x;
  std::int64_t y;
};

/// The pixel square in grid units: [x0, x1] x [y0, y1].
struct GridBox {
  std::int64_t x0, x1, y0, y1;
};

GridPoint to_grid(glm::dvec2 p) {
  return {static_cast<std::int64_t>(p.x * unit), static_cast<std::int64_t>(p.y * unit)};
}

GridBox pixel_square(glm::ivec2 pixel) {
  const std::int64_t cx = pixel.x * unit;
  const std::int64_t cy = pixel.y * unit;
  return {cx - half, cx + half, cy - half, cy + half};
}

// [listing edge_area]
// One edge's part of the area inside the box, by Green's theorem: the integral along the edge of
// h(y) = clamp(x(y), x0, x1) - x0 over the part of the edge inside the box's rows. Summed over
// the three edges of a closed triangle, it is the area of triangle and box, signed by winding.
Fraction edge_area(GridPoint a, GridPoint b, const GridBox& box) {
  if (a.y == b.y) return 0;  // a horizontal edge has dy = 0 all along
  const std::int64_t low = std::max(std::min(a.y, b.y), box.y0);
  const std::int64_t high = std::min(std::max(a.y, b.y), box.y1);
  if (low >= high) return 0;
  const Int128 dx = b.x - a.x;
  const Int128 dy = b.y - a.y;
  const auto x_at = [&](Fraction y) {
    return Fraction(a.x) + (y - Fraction(a.y)) * Fraction(dx, dy);
  };
  const auto h_at = [&](Fraction y) {
    return std::clamp(x_at(y), Fraction(box.x0), Fraction(box.x1)) - Fraction(box.x0);
  };
  // Between the rows' ends and the heights where the edge crosses x0 or x1, h is linear.
  std::array<Fraction, 4> ys = {Fraction(low)};
  std::size_t count = 1;
  if (dx != 0) {
    for (const std::int64_t x : {box.x0, box.x1}) {
      const Fraction y = Fraction(a.y) + (Fraction(x) - Fraction(a.x)) * Fraction(dy, dx);
      if (Fraction(low) < y && y < Fraction(high)) ys[count++] = y;
    }
  }
  if (count == 3 && ys[2] < ys[1]) std::swap(ys[1], ys[2]);
  ys[count++] = Fraction(high);
  Fraction area = 0;
  for (std::size_t k = 0; k + 1 < count; ++k) {
    area = area + (h_at(ys[k]) + h_at(ys[k + 1])) * (ys[k + 1] - ys[k]) / 2;  // a trapezoid
  }
  return dy > 0 ? area : Fraction(0) - area;
}
// [/listing]

// Where the pixel square lies against a triangle, decided from its four corners alone: inside
// when every corner is inside or on the triangle (which is convex), outside when every corner is
// on the outer side of one edge line. Neither: the square straddles an edge and needs the areas.
enum class SquarePlace { inside, outside, straddles };

SquarePlace place_of(const std::array<GridPoint, 3>& v, const GridBox& box) {
  const std::int64_t doubled =
      (v[1].x - v[0].x) * (v[2].y - v[0].y) - (v[2].x - v[0].x) * (v[1].y - v[0].y);
  const std::array<GridPoint, 4> corners = {
      {{box.x0, box.y0}, {box.x1, box.y0}, {box.x0, box.y1}, {box.x1, box.y1}}};
  bool all_inside = true;
  for (int k = 0; k < 3; ++k) {
    const GridPoint a = v[k], b = v[(k + 1) % 3];
    int inner = 0;
    for (const GridPoint& c : corners) {
      // Positive on the triangle's side of edge ab, whatever the winding.
      const std::int64_t side = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
      const std::int64_t toward = doubled > 0 ? side : -side;
      inner += toward > 0 ? 1 : 0;
      all_inside = all_inside && toward >= 0;
    }
    if (inner == 0) return SquarePlace::outside;
  }
  return all_inside ? SquarePlace::inside : SquarePlace::straddles;
}

Fraction magnitude(const Fraction& f) {
  return f < Fraction(0) ? Fraction(0) - f : f;
}

}  // namespace

void require_on_oracle_grid(const Triangle& triangle) {
  for (const glm::dvec2 v : triangle) {
    for (const double c : {v.x, v.y}) {
      if (!std::isfinite(c) || std::abs(c) > max_pixels) {
        throw std::invalid_argument("exact area: a vertex lies beyond ±32768 pixels");
      }
      if (c * unit != std::floor(c * unit)) {
        throw std::invalid_argument("exact area: a vertex is not on the 1/256 grid");
      }
    }
  }
}

Fraction exact_coverage(const Triangle& triangle, glm::ivec2 pixel) {
  require_on_oracle_grid(triangle);
  const GridBox box = pixel_square(pixel);
  const std::array<GridPoint, 3> v = {to_grid(triangle[0]), to_grid(triangle[1]),
                                      to_grid(triangle[2])};
  const Fraction signed_area =
      edge_area(v[0], v[1], box) + edge_area(v[1], v[2], box) + edge_area(v[2], v[0], box);
  return magnitude(signed_area) / Fraction(unit * unit);
}

Fraction exact_area(const Triangle& triangle) {
  require_on_oracle_grid(triangle);
  const GridPoint a = to_grid(triangle[0]), b = to_grid(triangle[1]), c = to_grid(triangle[2]);
  const Int128 twice = Int128{b.x - a.x} * (c.y - a.y) - Int128{c.x - a.x} * (b.y - a.y);
  return magnitude(Fraction(twice, Int128{2} * unit * unit));
}

std::vector<PixelCoverage> exact_coverages(const Triangle& triangle) {
  require_on_oracle_grid(triangle);
  const auto extent = [&](auto pick, int axis) {
    return pick({triangle[0][axis], triangle[1][axis], triangle[2][axis]});
  };
  const auto lowest = [](std::initializer_list<double> v) { return std::min(v); };
  const auto highest = [](std::initializer_list<double> v) { return std::max(v); };
  // Pixel i spans [i - 1/2, i + 1/2]: the pixels the extent reaches, edges included.
  const int first_x = static_cast<int>(std::floor(extent(lowest, 0) + 0.5));
  const int last_x = static_cast<int>(std::ceil(extent(highest, 0) - 0.5));
  const int first_y = static_cast<int>(std::floor(extent(lowest, 1) + 0.5));
  const int last_y = static_cast<int>(std::ceil(extent(highest, 1) - 0.5));
  const std::array<GridPoint, 3> v = {to_grid(triangle[0]), to_grid(triangle[1]),
                                      to_grid(triangle[2])};
  std::vector<PixelCoverage> covered;
  if (!(Fraction(0) < exact_area(triangle))) return covered;
  for (int y = first_y; y <= last_y; ++y) {
    for (int x = first_x; x <= last_x; ++x) {
      // Most pixels of a large triangle lie wholly inside or outside: no areas needed there.
      const SquarePlace place = place_of(v, pixel_square({x, y}));
      if (place == SquarePlace::outside) continue;
      const Fraction c =
          place == SquarePlace::inside ? Fraction(1) : exact_coverage(triangle, {x, y});
      if (Fraction(0) < c) covered.push_back({{x, y}, c});
    }
  }
  return covered;
}

Fraction edge_area_in_pixel(glm::dvec2 a, glm::dvec2 b, glm::ivec2 pixel) {
  require_on_oracle_grid({{a, b, b}});
  return edge_area(to_grid(a), to_grid(b), pixel_square(pixel)) / Fraction(unit * unit);
}

EdgeInPixelRow edge_in_pixel_row(glm::dvec2 a_pixels, glm::dvec2 b_pixels, glm::ivec2 pixel) {
  require_on_oracle_grid({{a_pixels, b_pixels, b_pixels}});
  const GridPoint a = to_grid(a_pixels), b = to_grid(b_pixels);
  const GridBox box = pixel_square(pixel);
  EdgeInPixelRow parts;
  const std::int64_t low = std::max(std::min(a.y, b.y), box.y0);
  const std::int64_t high = std::min(std::max(a.y, b.y), box.y1);
  if (a.y == b.y || low >= high) return parts;
  const Fraction slope(b.x - a.x, b.y - a.y);  // dx/dy
  const auto x_at = [&](Fraction y) { return Fraction(a.x) + (y - Fraction(a.y)) * slope; };
  // The heights where the edge crosses the pixel's sides split it into at most three parts.
  std::vector<Fraction> ys = {Fraction(low), Fraction(high)};
  if (a.x != b.x) {
    for (const std::int64_t x : {box.x0, box.x1}) {
      const Fraction y = Fraction(a.y) + (Fraction(x) - Fraction(a.x)) / slope;
      if (Fraction(low) < y && y < Fraction(high)) ys.push_back(y);
    }
  }
  std::sort(ys.begin(), ys.end());
  const Fraction sign = b.y > a.y ? 1 : -1;
  const Fraction grid_unit(unit);
  for (std::size_t k = 0; k + 1 < ys.size(); ++k) {
    const Fraction height = sign * (ys[k + 1] - ys[k]) / grid_unit;
    const Fraction mean_x = (x_at(ys[k]) + x_at(ys[k + 1])) / 2;
    if (mean_x < Fraction(box.x0)) {
      parts.left_height = parts.left_height + height;
    } else if (Fraction(box.x1) < mean_x) {
      parts.right_height = parts.right_height + height;
    } else {
      parts.inside_height = height;
      parts.inside_mean_x = (mean_x - Fraction(box.x0)) / grid_unit;
    }
  }
  return parts;
}

std::uint16_t coverage_16(const Fraction& coverage) {
  const Fraction c = std::clamp(coverage, Fraction(0), Fraction(1));
  // floor(65535 c + 1/2) = floor((2 * 65535 n + d) / (2 d)), all non-negative.
  const Int128 n = c.numerator(), d = c.denominator();
  return static_cast<std::uint16_t>((2 * 65535 * n + d) / (2 * d));
}

}  // namespace tri::ch09
