#include "chapters/04_scanline/step_figures.hpp"

#include <cstdint>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include "chapters/03_interpolate_fill/diagram_support.hpp"
#include "chapters/04_scanline/boundaries.hpp"
#include "chapters/04_scanline/diagram_support.hpp"
#include "chapters/04_scanline/lower_half.hpp"
#include "chapters/04_scanline/outline_steps.hpp"
#include "chapters/04_scanline/scanline_fills.hpp"

namespace tri::ch04::figures {
namespace {

namespace dc = diagram_colors;

constexpr Color boundary_a = dc::vermillion;
constexpr Color boundary_b = dc::blue;

// Fills every pixel the step wrote, in `color`.
void fill_written(PixelDiagram& diagram, const Canvas& drawn, Color color) {
  for (int y = 0; y < drawn.height(); ++y) {
    for (int x = 0; x < drawn.width(); ++x) {
      if (drawn.write_count(x, y) > 0) diagram.fill({x, y}, color);
    }
  }
}

// Fills every pixel the step wrote in the colour it wrote: vermillion for A, blue for B.
void fill_boundaries(PixelDiagram& diagram, const Canvas& drawn) {
  for (int y = 0; y < drawn.height(); ++y) {
    for (int x = 0; x < drawn.width(); ++x) {
      if (drawn.write_count(x, y) == 0) continue;
      diagram.fill({x, y}, drawn.pixel(x, y));
    }
  }
}

Step fill_step(void (*fill)(Canvas&, glm::ivec2, glm::ivec2, glm::ivec2, Color)) {
  return [fill](Canvas& canvas, glm::ivec2 a, glm::ivec2 b, glm::ivec2 c) {
    fill(canvas, a, b, c, colors::white);
  };
}

// A fill step on the green triangle: the triangle sorted by y, the step drawn on a counting
// canvas, and the diagram with every pixel the step wrote filled.
struct FilledStep {
  SortedTriangle t;
  Canvas drawn;
  PixelDiagram diagram;
};

FilledStep filled_step(void (*fill)(Canvas&, glm::ivec2, glm::ivec2, glm::ivec2, Color),
                       std::string title) {
  const auto [a, b, c] = diagram_triangle().vertices;
  FilledStep step{sort_by_y(a, b, c), drawn_by(fill_step(fill), diagram_triangle()),
                  green_diagram(std::move(title))};
  fill_written(step.diagram, step.drawn, dc::covered);
  return step;
}

// Hatches the pixels a boundary would need to be connected: between its points on two
// neighbouring rows, on the upper row. Returns {breaks, pixels}.
std::pair<int, int> hatch_gaps(PixelDiagram& diagram, int first_row,
                               const std::vector<std::int64_t>& xs) {
  int breaks = 0, pixels = 0;
  for (std::size_t k = 0; k + 1 < xs.size(); ++k) {
    const std::int64_t step = xs[k + 1] - xs[k];
    if (std::llabs(step) <= 1) continue;
    ++breaks;
    const int direction = step > 0 ? 1 : -1;
    for (std::int64_t s = 1; s < std::llabs(step); ++s) {
      diagram.mark({static_cast<int>(xs[k] + direction * s), first_row + static_cast<int>(k) + 1},
                   PixelMark::hatch, dc::dark_gray);
      ++pixels;
    }
  }
  return {breaks, pixels};
}

}  // namespace

SvgFigure outlines() {
  const Canvas drawn = drawn_by([](Canvas& canvas, glm::ivec2 a, glm::ivec2 b,
                                   glm::ivec2 c) { draw_outline(canvas, a, b, c, colors::white); },
                                diagram_triangle());
  PixelDiagram diagram =
      green_diagram("Step 1: Bresenham's outline shows the triangle, fills nothing");
  fill_written(diagram, drawn, dc::covered);
  diagram.legend_fill("outline pixel (chapter 01's Bresenham)", dc::covered);
  diagram.legend_line("ideal triangle edges", dc::black);
  return SvgFigure{"04_outlines", diagram.svg()};
}

SvgFigure sorted_boundaries() {
  const Canvas drawn = drawn_by(draw_sorted_boundaries, diagram_triangle());
  PixelDiagram diagram = green_diagram("Step 2: boundary A runs t0 to t2, boundary B bends at t1");
  fill_boundaries(diagram, drawn);
  diagram.legend_fill("boundary A: the long edge t0-t2", boundary_a);
  diagram.legend_fill("boundary B: t0-t1, then t1-t2", boundary_b);
  diagram.legend_line("ideal triangle edges", dc::black);
  return SvgFigure{"04_sorted_boundaries", diagram.svg()};
}

SvgFigure lower_half_points() {
  const auto [a, b, c] = diagram_triangle().vertices;
  const SortedTriangle t = sort_by_y(a, b, c);
  const Canvas drawn = drawn_by(draw_lower_half_boundary_points, diagram_triangle());
  PixelDiagram diagram =
      green_diagram("Step 3: one point per row on each boundary leaves gaps where it is shallow");
  fill_boundaries(diagram, drawn);
  std::vector<std::int64_t> xs_a, xs_b;
  for (int y = t.p0.y; y <= t.p1.y; ++y) {
    const SpanEnds ends = lower_half_ends(t, y);
    xs_a.push_back(ends.a);
    xs_b.push_back(ends.b);
  }
  const auto [breaks_a, missing_a] = hatch_gaps(diagram, t.p0.y, xs_a);
  const auto [breaks_b, missing_b] = hatch_gaps(diagram, t.p0.y, xs_b);
  const glm::ivec2 b_at_t1{static_cast<int>(xs_b.back()), t.p1.y};
  diagram.mark(b_at_t1, PixelMark::square);
  diagram.label(glm::dvec2(b_at_t1) + glm::dvec2(0.5, 0), "B on row t1.y, not t1",
                LabelPlace::above_right);
  diagram.legend_fill("point on boundary A", boundary_a);
  diagram.legend_fill("point on boundary B", boundary_b);
  diagram.legend_mark("gap: needed to connect", PixelMark::hatch, dc::dark_gray);
  diagram.legend_mark("B's last point (the +1)", PixelMark::square);
  diagram.legend_line("ideal edges", dc::black);
  diagram.legend_note(
      "A breaks " + std::to_string(breaks_a) + " times (" + std::to_string(missing_a) +
      " pixels missing), B " + std::to_string(breaks_b) + " times (" + std::to_string(missing_b) +
      " pixels). On row " + std::to_string(t.p1.y) + ", B is at x = " + std::to_string(b_at_t1.x) +
      ", not t1.x = " + std::to_string(t.p1.x) + ".");
  return SvgFigure{"04_lower_half_points", diagram.svg()};
}

SvgFigure lower_half_filled() {
  auto [t, drawn, diagram] = filled_step(
      fill_lower_half, "Step 4: each lower-half row filled from A to B; B lags behind its edge");
  const auto [a, b, c] = diagram_triangle().vertices;
  int lost = 0;
  for (int y = t.p0.y; y <= t.p1.y; ++y) {
    for (int x = 0; x < drawn.width(); ++x) {
      if (drawn.write_count(x, y) == 0 && ch03::figures::centre_in_triangle(a, b, c, {x, y})) {
        diagram.mark({x, y}, PixelMark::cross, dc::vermillion);
        ++lost;
      }
    }
  }
  diagram.legend_fill("drawn by the lower half", dc::covered);
  diagram.legend_mark("centre inside, not drawn (B's +1)", PixelMark::cross, dc::vermillion);
  diagram.legend_line("ideal edges", dc::black);
  diagram.legend_note(std::to_string(lost) + " centres in rows t0.y to t1.y are left out.");
  return SvgFigure{"04_lower_half_filled", diagram.svg()};
}

SvgFigure two_loops() {
  const Canvas drawn = drawn_by(fill_step(fill_two_loops), diagram_triangle());
  PixelDiagram diagram = green_diagram("Step 5: two loops fill both halves and both draw row t1.y");
  int twice = 0;
  for (int y = 0; y < drawn.height(); ++y) {
    for (int x = 0; x < drawn.width(); ++x) {
      const int count = drawn.write_count(x, y);
      if (count == 0) continue;
      diagram.fill({x, y}, count > 1 ? dc::orange : dc::covered);
      if (count > 1) {
        diagram.mark({x, y}, PixelMark::hatch, dc::black);
        ++twice;
      }
    }
  }
  diagram.legend_fill("drawn once", dc::covered);
  diagram.legend_fill("drawn twice (row t1.y)", dc::orange);
  diagram.legend_mark("hatched: drawn twice", PixelMark::hatch);
  diagram.legend_line("ideal edges", dc::black);
  diagram.legend_note(std::to_string(twice) + " pixels of row t1.y are drawn by both loops.");
  return SvgFigure{"04_two_loops", diagram.svg()};
}

SvgFigure single_loop() {
  auto [t, drawn, diagram] = filled_step(
      fill_single_loop, "Step 6: one loop with second_half, each pixel once, top row included");
  for (int x = 0; x < drawn.width(); ++x) {
    if (drawn.write_count(x, t.p2.y) > 0) diagram.mark({x, t.p2.y}, PixelMark::square);
  }
  diagram.legend_fill("drawn once", dc::covered);
  diagram.legend_mark("row t2.y: the published loop stops before it", PixelMark::square);
  diagram.legend_line("ideal edges", dc::black);
  return SvgFigure{"04_single_loop", diagram.svg()};
}

}  // namespace tri::ch04::figures
