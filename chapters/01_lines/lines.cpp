#include "chapters/01_lines/lines.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <utility>

#include "chapters/01_lines/interpolate.hpp"

namespace tri::ch01 {
namespace {

int round_to_int(double v) {
  return static_cast<int>(std::floor(v + 0.5));
}

}  // namespace

// [listing draw_line_gambetta]
void draw_line_gambetta(Canvas& canvas, glm::ivec2 p0, glm::ivec2 p1, Color color) {
  // 64-bit differences: endpoints 2^31 apart overflow int.
  if (std::abs(std::int64_t{p1.x} - p0.x) > std::abs(std::int64_t{p1.y} - p0.y)) {
    // Mostly horizontal: y = f(x), one pixel per column.
    if (p0.x > p1.x) std::swap(p0, p1);
    const auto ys = interpolate(p0.x, p0.y, p1.x, p1.y);
    for (int x = p0.x; x <= p1.x; ++x) canvas.put_pixel(x, round_to_int(ys[x - p0.x]), color);
  } else {
    // Mostly vertical (or a single point): x = f(y), one pixel per row.
    if (p0.y > p1.y) std::swap(p0, p1);
    const auto xs = interpolate(p0.y, p0.x, p1.y, p1.x);
    for (int y = p0.y; y <= p1.y; ++y) canvas.put_pixel(round_to_int(xs[y - p0.y]), y, color);
  }
}
// [/listing]

// [listing draw_line_dda]
void draw_line_dda(Canvas& canvas, glm::ivec2 p0, glm::ivec2 p1, Color color) {
  const double dx = static_cast<double>(p1.x) - p0.x;
  const double dy = static_cast<double>(p1.y) - p0.y;
  const double steps = std::max(std::abs(dx), std::abs(dy));
  if (steps == 0) {
    canvas.put_pixel(p0, color);
    return;
  }
  const double step_x = dx / steps;  // one of the two is exactly ±1
  const double step_y = dy / steps;
  double x = p0.x;
  double y = p0.y;
  const auto n = static_cast<std::int64_t>(steps);
  for (std::int64_t i = 0; i <= n; ++i) {
    // Round both coordinates: the blog's (int)x truncates 4.9999... down to 4.
    canvas.put_pixel(round_to_int(x), round_to_int(y), color);
    x += step_x;
    y += step_y;
  }
}
// [/listing]

void draw_line_bresenham(Canvas& canvas, glm::ivec2 p0, glm::ivec2 p1, Color color) {
  // Work in 64 bits: differences of ±2^30 coordinates, doubled and multiplied, need them.
  std::int64_t x0 = p0.x, y0 = p0.y, x1 = p1.x, y1 = p1.y;
  const bool steep = std::abs(y1 - y0) > std::abs(x1 - x0);
  if (steep) {  // walk along y instead: swap the roles of x and y
    std::swap(x0, y0);
    std::swap(x1, y1);
  }
  if (x0 > x1) {  // always walk towards increasing major coordinate
    std::swap(x0, x1);
    std::swap(y0, y1);
  }
  const std::int64_t dx = x1 - x0;
  const std::int64_t dy = std::abs(y1 - y0);
  const std::int64_t y_step = y1 > y0 ? 1 : -1;
  const std::int64_t major_size = steep ? canvas.height() : canvas.width();

  // Walk only the steps whose major coordinate is on the canvas.
  const std::int64_t first = std::max<std::int64_t>(x0, 0);
  const std::int64_t last = std::min<std::int64_t>(x1, major_size - 1);
  if (first > last) return;
  // After k steps the minor coordinate has moved m = ceil((2 dy k - dx) / (2 dx)) times (0 when
  // negative), and error = 2 dy k - 2 dx m lies in (-dx, dx]: the state the loop would reach.
  // 2 dy k reaches 2^63 for endpoints at ±2^30, so this one product takes 128 bits.
  __extension__ using Wide = __int128;
  const std::int64_t k = first - x0;
  const std::int64_t moves =
      dx == 0 ? 0 : static_cast<std::int64_t>((Wide{2} * dy * k + dx - 1) / (Wide{2} * dx));
  std::int64_t error = 2 * dy * k - 2 * dx * moves;
  std::int64_t y = y0 + y_step * moves;
  const std::int64_t minor_size = steep ? canvas.width() : canvas.height();
  // [listing bresenham_walk]
  for (std::int64_t x = first; x <= last; ++x) {
    if (y < 0 || y >= minor_size) {
      // Off the canvas across the line: write nothing (a far line may cross it later).
    } else if (steep) {
      canvas.put_pixel(static_cast<int>(y), static_cast<int>(x), color);
    } else {
      canvas.put_pixel(static_cast<int>(x), static_cast<int>(y), color);
    }
    error += 2 * dy;
    if (error > dx) {  // the line passed the midpoint above this pixel: move one row
      y += y_step;
      error -= 2 * dx;
    }
  }
  // [/listing]
}

void draw_line_midpoint(Canvas& canvas, glm::ivec2 p0, glm::ivec2 p1, Color color) {
  std::int64_t dx = std::abs(static_cast<std::int64_t>(p1.x) - p0.x);
  std::int64_t dy = std::abs(static_cast<std::int64_t>(p1.y) - p0.y);
  const int sign_x = p0.x < p1.x ? 1 : -1;
  const int sign_y = p0.y < p1.y ? 1 : -1;
  const bool steep = dy > dx;
  if (steep) std::swap(dx, dy);  // dx is now the major length, dy the minor one
  // e = 2 dx * (signed distance of the next midpoint below the line); starts at dx - 2 dy.
  // [listing midpoint_walk]
  std::int64_t e = dx - 2 * dy;
  std::int64_t x = p0.x;  // 64 bits: the walk steps once past p1
  std::int64_t y = p0.y;
  for (std::int64_t i = 0; i <= dx; ++i) {  // <=: the blog's `i <= dx` from 1 loses the endpoint
    canvas.put_pixel(static_cast<int>(x), static_cast<int>(y), color);
    if (steep) {
      y += sign_y;
    } else {
      x += sign_x;
    }
    if (e < 0) {  // the midpoint is below the line: step the minor coordinate too
      if (steep) {
        x += sign_x;
      } else {
        y += sign_y;
      }
      e += 2 * dx - 2 * dy;
    } else {
      e -= 2 * dy;
    }
  }
  // [/listing]
}

}  // namespace tri::ch01
