// Chapter 01's figures: a star of lines in every octant drawn by each algorithm, and a close-up
// of the tie cases where the algorithms part ways.
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include "figures.hpp"
#include "line_algorithms.hpp"
#include "line_reference.hpp"

namespace {

using tri::Canvas;
using tri::ch01::LineAlgorithm;

constexpr int magnification = 6;

// 24 spokes, 15 degrees apart, from the centre of a 65x65 canvas: every octant, both directions.
Canvas star(const LineAlgorithm& algorithm) {
  Canvas canvas(65, 65);
  const glm::ivec2 centre(32, 32);
  for (int i = 0; i < 24; ++i) {
    const double angle = i * std::numbers::pi / 12.0;
    const glm::ivec2 tip(centre.x + static_cast<int>(std::lround(30 * std::cos(angle))),
                         centre.y + static_cast<int>(std::lround(30 * std::sin(angle))));
    const tri::Color color = i % 2 == 0 ? tri::colors::white : tri::colors::cyan;
    algorithm.draw(canvas, centre, tip, color);
  }
  return canvas;
}

// Lines whose exact path passes halfway between two pixels at some steps, each drawn twice: from
// its left end in the upper copy, from its right end in the lower one. White: the nearest pixel
// (ties rounded up); red: a different pixel; dark grey: the nearest pixel, not drawn.
Canvas tie_close_up(const LineAlgorithm& algorithm) {
  Canvas canvas(26, 31, tri::Color{40, 40, 40, 255});
  const glm::ivec2 lines[][2] = {
      {{1, 1}, {13, 2}}, {{1, 8}, {13, 14}}, {{15, 1}, {18, 13}}, {{20, 13}, {22, 1}}};
  for (const int copy : {0, 1}) {
    const glm::ivec2 shift(0, copy == 0 ? 16 : 0);
    for (const auto& line : lines) {
      const glm::ivec2 a = line[0] + shift, b = line[1] + shift;
      Canvas drawn(canvas.width(), canvas.height());
      drawn.enable_write_counts();
      const auto [from, to] = copy == 0 ? std::pair(a, b) : std::pair(b, a);
      algorithm.draw(drawn, from, to, tri::colors::white);
      for (const auto& exact : tri::ch01::exact_line_pixels(a, b)) {
        canvas.put_pixel(exact.pixel, tri::Color{90, 90, 90, 255});
      }
      for (int y = 0; y < drawn.height(); ++y) {
        for (int x = 0; x < drawn.width(); ++x) {
          if (drawn.write_count(x, y) == 0) continue;
          const auto major = std::abs(b.x - a.x) >= std::abs(b.y - a.y) ? x : y;
          const bool nearest =
              tri::ch01::exact_line_pixel_at(a, b, major).pixel == glm::ivec2(x, y);
          canvas.put_pixel(x, y, nearest ? tri::colors::white : tri::colors::red);
        }
      }
    }
  }
  return canvas;
}

}  // namespace

int main(int argc, char** argv) {
  return tri::run_chapter_program(
      argc, argv, "01_lines",
      "Chapter 01, lines: draws a star of 24 lines (every octant) with each of the four line\n"
      "algorithms (01_star_<algorithm>.png) and a close-up of lines that pass exactly halfway\n"
      "between pixels, drawn in both directions (01_ties_<algorithm>.png).",
      [](tri::FigureWriter& figures) {
        for (const auto& algorithm : tri::ch01::line_algorithms) {
          figures.save_png("01_star_" + std::string(algorithm.name),
                           tri::magnified(star(algorithm), magnification));
          figures.save_png("01_ties_" + std::string(algorithm.name),
                           tri::magnified(tie_close_up(algorithm), 12));
        }
      });
}
