// Chapter 02's figures: Gambetta's Figure 7-1, tinyrenderer's three test triangles as outlines
// with a zoom on the sharp top of the first, and a diagram of where the three lines meet.
#include <algorithm>
#include <array>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "chapters/01_lines/line_reference.hpp"
#include "chapters/01_lines/line_steps.hpp"
#include "chapters/02_wireframe/example_triangles.hpp"
#include "chapters/02_wireframe/wireframe.hpp"
#include "common/centered_view.hpp"
#include "common/figures.hpp"
#include "common/pixel_diagram.hpp"

namespace {

using tri::point_text;
using tri::Canvas;
using tri::LabelPlace;
using tri::PixelDiagram;
using tri::PixelMark;
using Vertices = std::array<glm::ivec2, 3>;
namespace dc = tri::diagram_colors;

std::size_t drawn_count(const Canvas& canvas, tri::Color background) {
  return static_cast<std::size_t>(std::count_if(canvas.pixels().begin(), canvas.pixels().end(),
                                                [&](tri::Color c) { return c != background; }));
}

// Figure 7-1: (-200,-250), (200,50), (20,250) in Gambetta's centred coordinates.
tri::SvgFigure gambetta_figure_7_1() {
  const int size = tri::ch02::figure_7_1_canvas_size;
  Canvas canvas(size, size, tri::colors::white);
  tri::CenteredView view(canvas);
  const auto& centred = tri::ch02::figure_7_1_triangle;
  Vertices v{};
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = view.to_canvas(centred[i]);
  tri::ch02::draw_wireframe_triangle(canvas, v[0], v[1], v[2], dc::black);

  PixelDiagram diagram({0, 0}, {599, 599},
                       "Gambetta's Figure 7-1: three lines, " +
                           std::to_string(drawn_count(canvas, tri::colors::white)) +
                           " pixels, on a 600x600 canvas with its origin moved to the middle",
                       1.25);  // 25 units between numbered ticks, room for "100"
  diagram.fill_from(canvas, tri::colors::white);
  const std::array<LabelPlace, 3> places{LabelPlace::right, LabelPlace::right, LabelPlace::left};
  for (std::size_t i = 0; i < v.size(); ++i) {
    diagram.point(v[i], dc::vermillion, 4);
    diagram.label(
        v[i],
        "P" + std::to_string(i) + " " + point_text(centred[i]) + " = canvas " + point_text(v[i]),
        places[i]);
  }
  diagram.point({300, 300}, dc::blue, 3);
  diagram.label({300, 300}, "origin of the centred coordinates, canvas (300, 300)",
                LabelPlace::below_right, dc::blue);
  diagram.legend_fill("drawn by draw_wireframe_triangle", dc::black);
  diagram.legend_note("Vertices (dots): Pi (Gambetta's centred coordinates) = canvas coordinates.");
  return tri::SvgFigure{"02_wireframe_figure_7_1", diagram.svg()};
}

using tri::ch02::tinyrenderer_triangles;

// How the figure shows tinyrenderer's red, white and green on a white page.
struct DiagramColor {
  tri::Color color;
  std::string name;
};
const std::array<DiagramColor, 3> tinyrenderer_diagram_colors{{
    {dc::vermillion, "vermillion (red in tinyrenderer)"},
    {dc::black, "black (white in tinyrenderer)"},
    {dc::bluish_green, "green"},
}};

constexpr glm::ivec2 apex_first{40, 146}, apex_last{60, 163};

tri::SvgFigure tinyrenderer_figure() {
  PixelDiagram diagram({0, 0}, {199, 199},
                       "tinyrenderer lesson 2's three test triangles as outlines, 200x200 image",
                       3);
  diagram.show_centres(false);
  std::string sizes;
  for (std::size_t t = 0; t < tinyrenderer_triangles.size(); ++t) {
    const auto& v = tinyrenderer_triangles[t].vertices;
    const int size = tri::ch02::tinyrenderer_image_size;
    Canvas canvas(size, size, tri::colors::white);
    tri::ch02::draw_wireframe_triangle(canvas, v[0], v[1], v[2],
                                       tinyrenderer_diagram_colors[t].color);
    diagram.fill_from(canvas, tri::colors::white);
    sizes += (sizes.empty() ? "" : ", ") + std::to_string(drawn_count(canvas, tri::colors::white));
  }
  const std::array<std::array<LabelPlace, 3>, 3> places{{
      {LabelPlace::below_right, LabelPlace::above_left, LabelPlace::right},
      {LabelPlace::right, LabelPlace::left, LabelPlace::above_left},
      {LabelPlace::right, LabelPlace::below_left, LabelPlace::above_right},
  }};
  for (std::size_t t = 0; t < tinyrenderer_triangles.size(); ++t) {
    for (std::size_t i = 0; i < 3; ++i) {
      const glm::ivec2 p = tinyrenderer_triangles[t].vertices[i];
      diagram.point(p, dc::dark_gray, 2.5);
      diagram.label(p, point_text(p), places[t][i], dc::dark_gray);
    }
  }
  diagram.frame(apex_first, apex_last, dc::blue, 1.5, true);
  for (const auto& c : tinyrenderer_diagram_colors) diagram.legend_fill(c.name, c.color);
  diagram.legend_line("the sharp top zoomed in 02_wireframe_tinyrenderer_apex", dc::blue, true);
  diagram.legend_note("Outlines of " + sizes +
                      " pixels; vertices labelled with their coordinates.");
  return tri::SvgFigure{"02_wireframe_tinyrenderer", diagram.svg()};
}

// Each edge's pixels in its own colour, the pixels two edges draw hatched, the ideal edges and
// every tie step of an edge (its two candidates ringed), over pixels first..last.
std::string edges_diagram(const Vertices& v, glm::ivec2 first, glm::ivec2 last,
                          const std::string& title, const std::array<LabelPlace, 3>& places,
                          double cell) {
  PixelDiagram diagram(first, last, title, cell);
  const std::array<tri::Color, 3> colors{dc::orange, dc::sky_blue, dc::bluish_green};
  const std::array<std::string, 3> names{"P0-P1", "P1-P2", "P2-P0"};
  const auto edges = tri::ch02::outline_edge_pixels(v[0], v[1], v[2]);
  std::map<std::pair<int, int>, int> writes;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    diagram.fill(edges[i], colors[i]);
    for (const auto p : edges[i]) ++writes[{p.x, p.y}];
  }
  bool any_twice = false;
  for (const auto& [p, count] : writes) {
    if (count < 2) continue;
    any_twice = true;
    diagram.fill(glm::ivec2(p.first, p.second), dc::yellow);
    diagram.mark(glm::ivec2(p.first, p.second), PixelMark::hatch, dc::dark_gray);
  }
  bool any_tie = false;
  for (std::size_t i = 0; i < 3; ++i) {
    const glm::ivec2 a = v[i], b = v[(i + 1) % 3];
    const bool x_major = std::abs(b.x - a.x) >= std::abs(b.y - a.y);
    for (const auto& exact : tri::ch01::exact_line_pixels(a, b)) {
      if (!exact.tie) continue;
      any_tie = true;
      diagram.mark(exact.pixel, PixelMark::ring);
      diagram.mark(exact.pixel - (x_major ? glm::ivec2(0, 1) : glm::ivec2(1, 0)), PixelMark::ring);
    }
    diagram.line(a, b, dc::black, 2);
  }
  for (std::size_t i = 0; i < 3; ++i) {
    if (v[i].x >= first.x && v[i].x <= last.x && v[i].y >= first.y && v[i].y <= last.y) {
      diagram.vertex(v[i], "P" + std::to_string(i), places[i]);
    }
  }
  for (std::size_t i = 0; i < 3; ++i) {
    const bool shown = std::any_of(edges[i].begin(), edges[i].end(), [&](glm::ivec2 p) {
      return p.x >= first.x && p.x <= last.x && p.y >= first.y && p.y <= last.y;
    });
    if (shown) diagram.legend_fill("drawn by edge " + names[i] + " only", colors[i]);
  }
  if (any_twice) {
    diagram.legend_fill("drawn by two edges (written twice, hatched)", dc::yellow);
  }
  if (any_tie) {
    diagram.legend_mark("tie: the edge passes exactly halfway between two ringed centres",
                        PixelMark::ring);
  }
  diagram.legend_line("ideal edges", dc::black);
  return diagram.svg();
}

tri::SvgFigure joints_figure() {
  return tri::SvgFigure{
      "02_wireframe_joints",
      edges_diagram({{{1, 1}, {7, 3}, {3, 6}}}, {0, 0}, {9, 7},
                    "Where the lines meet: each vertex is written by both of its edges",
                    {LabelPlace::below_right, LabelPlace::right, LabelPlace::above_right}, 40)};
}

tri::SvgFigure tinyrenderer_apex_figure() {
  const Vertices& v = tinyrenderer_triangles[0].vertices;
  return tri::SvgFigure{
      "02_wireframe_tinyrenderer_apex",
      edges_diagram(v, apex_first, apex_last,
                    "tinyrenderer's red triangle, top (50, 160): both edges also draw (50, 159)",
                    {LabelPlace::right, LabelPlace::above_right, LabelPlace::right}, 24)};
}

}  // namespace

int main(int argc, char** argv) {
  return tri::run_chapter_program(
      argc, argv, "02_wireframe",
      "Chapter 02, wireframe triangles: Figure 7-1, tinyrenderer's triangles, the joints.",
      {gambetta_figure_7_1, tinyrenderer_figure, tinyrenderer_apex_figure, joints_figure});
}
