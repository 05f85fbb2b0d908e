#include "chapters/04_scanline/check_figures.hpp"

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "chapters/03_interpolate_fill/diagram_support.hpp"
#include "chapters/04_scanline/boundaries.hpp"
#include "chapters/04_scanline/diagram_support.hpp"
#include "chapters/04_scanline/scanline_fills.hpp"

namespace tri::ch04::figures {
namespace {

namespace dc = diagram_colors;

// Which loop variants draw a pixel, one category per pixel.
enum class Drawn { none, both, only_two_loops, only_single_loop, not_by_published };

struct Variants {
  Canvas two, one, published;
};

Variants draw_variants(const ch02::TinyrendererTriangle& t) {
  const auto with = [](void (*fill)(Canvas&, glm::ivec2, glm::ivec2, glm::ivec2, Color)) {
    return [fill](Canvas& canvas, glm::ivec2 a, glm::ivec2 b, glm::ivec2 c) {
      fill(canvas, a, b, c, colors::white);
    };
  };
  return {drawn_by(with(fill_two_loops), t), drawn_by(with(fill_single_loop), t),
          drawn_by(with(fill_single_loop_as_published), t)};
}

Drawn category(const Variants& v, int x, int y) {
  const bool two = v.two.write_count(x, y) > 0, one = v.one.write_count(x, y) > 0;
  if (one && v.published.write_count(x, y) == 0) return Drawn::not_by_published;
  if (two && one) return Drawn::both;
  if (two) return Drawn::only_two_loops;
  if (one) return Drawn::only_single_loop;
  return Drawn::none;
}

constexpr Color only_two_color = dc::vermillion;
constexpr Color only_one_color = dc::sky_blue;
constexpr Color unreached_color = dc::yellow;

// Counts per category, in the order only two loops, only single loop, not by published.
using Counts = std::array<int, 3>;

// Paints the variants' categories on the diagram: zoomed with marks, or small with dots.
Counts paint_differences(PixelDiagram& diagram, const Variants& v, bool zoomed) {
  Counts counts{};
  for (int y = 0; y < v.two.height(); ++y) {
    for (int x = 0; x < v.two.width(); ++x) {
      const Drawn d = category(v, x, y);
      if (d == Drawn::none) continue;
      if (d == Drawn::both) {
        diagram.fill({x, y}, dc::covered);
        continue;
      }
      const Color color = d == Drawn::only_two_loops     ? only_two_color
                          : d == Drawn::only_single_loop ? only_one_color
                                                         : unreached_color;
      ++counts[d == Drawn::only_two_loops ? 0 : d == Drawn::only_single_loop ? 1 : 2];
      diagram.fill({x, y}, color);
      if (!zoomed) {
        diagram.point({x, y}, color == unreached_color ? dc::black : color, 2.5);
        continue;
      }
      diagram.mark({x, y}, d == Drawn::only_two_loops     ? PixelMark::cross
                           : d == Drawn::only_single_loop ? PixelMark::ring
                                                          : PixelMark::square);
    }
  }
  return counts;
}

std::string counts_note(const Counts& counts) {
  return std::to_string(counts[0]) + " only in the two loops, " + std::to_string(counts[1]) +
         " only in the single loop, " + std::to_string(counts[2]) + " never reached as published";
}

PixelDiagram whole_triangle_panel(const ch02::TinyrendererTriangle& t, const char* name,
                                  glm::ivec2 first, glm::ivec2 last, double cell) {
  PixelDiagram panel(first, last, std::string("The ") + name + " triangle", cell);
  panel.show_centres(false);
  const Counts counts = paint_differences(panel, draw_variants(t), false);
  const auto [a, b, c] = t.vertices;
  panel.triangle(a, b, c, dc::black, 0.75);
  const SortedTriangle s = sort_by_y(a, b, c);
  panel.vertex(s.p0, "t0", LabelPlace::right);
  panel.vertex(s.p1, "t1", LabelPlace::left);
  panel.vertex(s.p2, "t2", LabelPlace::right);
  panel.legend_fill("both", dc::covered);
  panel.legend_fill("only two loops", only_two_color);
  panel.legend_fill("only single loop", only_one_color);
  panel.legend_fill("row t2.y, missing as published", unreached_color);
  panel.legend_note(std::to_string(counts[0]) + " only two loops, " + std::to_string(counts[1]) +
                    " only single loop, " + std::to_string(counts[2]) + " on row t2.y");
  return panel;
}

}  // namespace

SvgFigure loop_differences() {
  PixelDiagram diagram =
      green_diagram("Where step 5's two loops and step 6's single loop part ways (green triangle)");
  const Counts counts = paint_differences(diagram, draw_variants(diagram_triangle()), true);
  diagram.legend_fill("drawn by both", dc::covered);
  diagram.legend_fill("only by the two loops", only_two_color);
  diagram.legend_mark("only by the two loops", PixelMark::cross);
  diagram.legend_fill("only by the single loop", only_one_color);
  diagram.legend_mark("only by the single loop", PixelMark::ring);
  diagram.legend_fill("single loop only with row t2.y", unreached_color);
  diagram.legend_mark("row t2.y, missing as published", PixelMark::square);
  diagram.legend_line("ideal edges", dc::black);
  diagram.legend_note(counts_note(counts) + ".");
  return SvgFigure{"04_loop_differences", diagram.svg()};
}

SvgFigure loop_differences_red_white() {
  const std::array<PixelDiagram, 2> panels{
      whole_triangle_panel(ch02::tinyrenderer_triangles[0], "red", {6, 66}, {74, 164}, 4),
      whole_triangle_panel(ch02::tinyrenderer_triangles[1], "white", {66, -2}, {184, 184}, 3)};
  return SvgFigure{
      "04_loop_differences_red_white",
      side_by_side(panels,
                   "The same differences on the red and white triangles (dots: pixels that "
                   "differ)")};
}

SvgFigure truncation_close_up() {
  const ch02::TinyrendererTriangle& red = ch02::tinyrenderer_triangles[0];
  const auto [a, b, c] = red.vertices;
  const SortedTriangle t = sort_by_y(a, b, c);
  const Canvas drawn =
      drawn_by([](Canvas& canvas, glm::ivec2 p, glm::ivec2 q,
                  glm::ivec2 r) { fill_single_loop(canvas, p, q, r, colors::white); },
               red);
  constexpr glm::ivec2 first{6, 67}, last{25, 84};
  PixelDiagram diagram(first, last,
                       "The int cast cuts boundary A toward t0: pixels outside the edge drawn", 24);
  int outside = 0;
  for (int y = 67; y <= 84; ++y) {
    for (int x = 6; x <= 25; ++x) {
      if (drawn.write_count(x, y) == 0) continue;
      const bool inside = ch03::figures::centre_in_triangle(a, b, c, {x, y});
      diagram.fill({x, y}, inside ? dc::covered : dc::vermillion);
      if (!inside) {
        diagram.mark({x, y}, PixelMark::cross);
        ++outside;
      }
    }
  }
  // A's exact x on each row, and the column the cast keeps.
  const std::int64_t height = t.p2.y - t.p0.y;
  for (int y = t.p0.y; y <= 84; ++y) {
    const double exact = t.p0.x + double(t.p2.x - t.p0.x) * (y - t.p0.y) / double(height);
    diagram.point({exact, y}, dc::blue, 3.5);
  }
  for (const auto& [p, q] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}}) {
    diagram.line(p, q, dc::black, 1.5);
  }
  diagram.vertex(t.p0, "t0", LabelPlace::below_right);
  const glm::ivec2 named{10, 72};
  diagram.mark(named, PixelMark::square, dc::blue);
  diagram.legend_fill("drawn, centre inside", dc::covered);
  diagram.legend_fill("drawn, centre outside", dc::vermillion);
  diagram.legend_mark("drawn, centre outside", PixelMark::cross);
  diagram.legend_mark("(10, 72): A = 10.89, cast to 10", PixelMark::square, dc::blue);
  diagram.legend_line("ideal edges", dc::black);
  diagram.legend_note("Blue dots: boundary A's exact x on each row; the span starts at the");
  diagram.legend_note("column the int cast cuts it to, toward t0. " + std::to_string(outside) +
                      " pixels here are drawn though their centre is outside.");
  return SvgFigure{"04_truncation_close_up", diagram.svg()};
}

}  // namespace tri::ch04::figures
