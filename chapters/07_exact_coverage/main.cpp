// Chapter 07's figures, all pixel diagrams: the top-left rule on a fan of triangles, a mesh with
// its vertices on pixel centres drawn with and without the rule (write counts), a jittered mesh
// drawn by chapter 06 and by the fixed-point rasterizer, and two triangles sharing an edge.
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

#include "chapters/05_edge_function/edge_function_fill.hpp"
#include "chapters/06_barycentric/fill.hpp"
#include "chapters/07_exact_coverage/coverage_oracle.hpp"
#include "chapters/07_exact_coverage/exact_orientation.hpp"
#include "chapters/07_exact_coverage/fixed_point.hpp"
#include "chapters/07_exact_coverage/jittered_mesh.hpp"
#include "common/figures.hpp"
#include "common/pixel_diagram.hpp"
#include "common/random.hpp"

namespace {

using tri::Canvas;
using tri::Color;
using tri::LabelPlace;
using tri::PixelDiagram;
using tri::PixelMark;
using tri::Triangle;
namespace palette = tri::diagram_colors;

using DrawFunction = void (*)(Canvas&, const Triangle&, Color);

// The earlier chapters' fills as their registry entries draw them (vertices rounded first).
constexpr DrawFunction draw_barycentric =
    tri::draw_at_nearest_pixels<tri::ch06::fill_triangle_barycentric<double>>;
constexpr DrawFunction draw_edge_function =
    tri::draw_at_nearest_pixels<tri::ch05::fill_triangle_edge_function>;

// ---------------------------------------------------------------------------------------------
// Edge classes, drawn the way the rule reads them.

// The colours of the three edge classes, shared by every diagram that shows them.
constexpr Color top_edge_color = palette::vermillion;
constexpr Color left_edge_color = palette::blue;
constexpr Color other_edge_color = palette::black;

// The class of edge a -> b of a counter-clockwise triangle, by the oracle's own test.
enum class EdgeClass { top, left, other };
EdgeClass edge_class(glm::dvec2 a, glm::dvec2 b) {
  if (!tri::ch07::is_top_left_edge(a, b)) return EdgeClass::other;
  return a.y == b.y ? EdgeClass::top : EdgeClass::left;
}

// The triangle shrunk towards its incentre so that each edge moves inward by `inset` pixels:
// where its edge classes are drawn, so the two sides of a shared edge do not overlap.
Triangle inset_triangle(const Triangle& t, double inset) {
  const double la = glm::distance(t[1], t[2]), lb = glm::distance(t[2], t[0]),
               lc = glm::distance(t[0], t[1]);
  const glm::dvec2 incentre = (la * t[0] + lb * t[1] + lc * t[2]) / (la + lb + lc);
  const glm::dvec2 ab = t[1] - t[0], ac = t[2] - t[0];
  const double inradius = std::abs(ab.x * ac.y - ab.y * ac.x) / (la + lb + lc);
  const double scale = 1 - inset / inradius;
  Triangle inner;
  for (int i = 0; i < 3; ++i) inner[i] = incentre + scale * (t[i] - incentre);
  return inner;
}

// Each edge of the triangle as a line just inside it, coloured by its class in this triangle
// (solid for top and left, dashed for any other edge); inset past the rings on the centres.
void draw_edge_classes(PixelDiagram& diagram, const Triangle& triangle) {
  const Triangle t = tri::ch07::counter_clockwise(triangle);
  const Triangle inner = inset_triangle(t, 0.42);
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    const EdgeClass kind = edge_class(t[i], t[j]);
    const Color color = kind == EdgeClass::top    ? top_edge_color
                        : kind == EdgeClass::left ? left_edge_color
                                                  : other_edge_color;
    diagram.line(inner[i], inner[j], color, 3, kind == EdgeClass::other);
  }
}

void add_edge_class_legend(PixelDiagram& diagram) {
  diagram.legend_line("top edge (horizontal, triangle below)", top_edge_color);
  diagram.legend_line("left edge (triangle to its right)", left_edge_color);
  diagram.legend_line("other edge (right or bottom)", other_edge_color, true);
}

// Whether the centre of pixel p lies exactly on the segment a-b (ends included).
bool centre_on_segment(glm::dvec2 a, glm::dvec2 b, glm::ivec2 p) {
  const glm::dvec2 c(p);
  return tri::ch07::exact_orientation(a, b, c) == 0 && c.x >= std::min(a.x, b.x) &&
         c.x <= std::max(a.x, b.x) && c.y >= std::min(a.y, b.y) && c.y <= std::max(a.y, b.y);
}

bool centre_on_an_edge(const Triangle& t, glm::ivec2 p) {
  return centre_on_segment(t[0], t[1], p) || centre_on_segment(t[1], t[2], p) ||
         centre_on_segment(t[2], t[0], p);
}

std::string coordinates(glm::dvec2 p) {
  return "(" + std::to_string(static_cast<int>(p.x)) + ", " +
         std::to_string(static_cast<int>(p.y)) + ")";
}

// A vertex: a dot and its coordinates, set a little farther off than PixelDiagram::vertex does,
// so the label clears the ring on the vertex's centre.
void vertex_label(PixelDiagram& diagram, glm::dvec2 p, LabelPlace place, std::string name = "") {
  const double d = 0.22;
  const glm::dvec2 shift = place == LabelPlace::above_right   ? glm::dvec2(d, d)
                           : place == LabelPlace::above_left  ? glm::dvec2(-d, d)
                           : place == LabelPlace::below_right ? glm::dvec2(d, -d)
                           : place == LabelPlace::below_left  ? glm::dvec2(-d, -d)
                           : place == LabelPlace::right       ? glm::dvec2(d, 0)
                                                              : glm::dvec2(-d, 0);
  diagram.point(p, palette::black);
  diagram.label(p + shift, (name.empty() ? "" : name + " ") + coordinates(p), place);
}

// ---------------------------------------------------------------------------------------------
// The rule diagram: six triangles around one shared vertex, in the manner of the Direct3D
// rasterization-rules figures.

struct NamedTriangle {
  std::string name;
  Triangle vertices;
  Color color;
  glm::dvec2 name_at;
};

// The fan around V = (6,6), counter-clockwise from the right: spokes of slope 0 and ±1, outer
// edges of slope 0 and ±2, each through pixel centres. top_left_rule_test.cpp checks the owners
// of the spokes' centres and of V by hand.
std::vector<NamedTriangle> rule_fan() {
  const glm::dvec2 v{6, 6};
  return {
      {"A", {{v, {12, 6}, {10, 10}}}, palette::orange, {9.3, 7.5}},
      {"B", {{v, {10, 10}, {2, 10}}}, palette::sky_blue, {5.5, 8.5}},
      {"C", {{v, {2, 10}, {0, 6}}}, palette::bluish_green, {2.2, 7.5}},
      {"D", {{v, {0, 6}, {2, 2}}}, palette::yellow, {2.2, 4.5}},
      {"E", {{v, {2, 2}, {10, 2}}}, palette::purple, {5.5, 3.5}},
      {"F", {{v, {10, 2}, {12, 6}}}, palette::covered, {9.3, 4.5}},
  };
}

std::string top_left_rule_figure() {
  const std::vector<NamedTriangle> fan = rule_fan();
  PixelDiagram diagram({-1, 1}, {13, 11},
                       "The top-left rule: which triangle owns each ringed centre", 34);
  // Pixels: the colour of the triangle the oracle gives the centre to; rings on every centre
  // that lies exactly on an edge (or a vertex) of the fan.
  for (int y = 1; y <= 11; ++y) {
    for (int x = -1; x <= 13; ++x) {
      bool on_edge = false;
      for (const NamedTriangle& t : fan) {
        if (tri::ch07::oracle_covers(t.vertices, {x, y})) diagram.fill({x, y}, t.color);
        on_edge = on_edge || centre_on_an_edge(t.vertices, {x, y});
      }
      if (on_edge) diagram.mark({x, y}, PixelMark::ring);
    }
  }
  for (const NamedTriangle& t : fan) {
    const auto& [a, b, c] = t.vertices;
    diagram.triangle(a, b, c, palette::dark_gray, 1);
  }
  for (const NamedTriangle& t : fan) draw_edge_classes(diagram, t.vertices);
  for (const NamedTriangle& t : fan) diagram.label(t.name_at, t.name, LabelPlace::right);
  vertex_label(diagram, {6, 6}, LabelPlace::above_right, "V");
  vertex_label(diagram, {12, 6}, LabelPlace::above_right);
  vertex_label(diagram, {10, 10}, LabelPlace::above_right);
  vertex_label(diagram, {2, 10}, LabelPlace::above_left);
  vertex_label(diagram, {0, 6}, LabelPlace::above_left);
  vertex_label(diagram, {2, 2}, LabelPlace::below_left);
  vertex_label(diagram, {10, 2}, LabelPlace::below_right);
  for (const NamedTriangle& t : fan) diagram.legend_fill("owned by " + t.name, t.color);
  diagram.legend_fill("owned by none", palette::empty);
  diagram.legend_mark("centre exactly on an edge", PixelMark::ring);
  add_edge_class_legend(diagram);
  diagram.legend_line("exact edge", palette::dark_gray);
  diagram.legend_note("Each triangle's edges are drawn just inside it, in their class there.");
  diagram.legend_note("A ringed centre goes to the triangle whose edges through it are all");
  diagram.legend_note("top or left: V lies on six triangles and goes to F alone.");
  return diagram.svg();
}

// ---------------------------------------------------------------------------------------------
// Write counts: how many times each pixel was drawn, as a count map.

constexpr Color drawn_once = palette::light_gray;
constexpr Color drawn_twice = palette::orange;
constexpr Color drawn_more = palette::blue;

// Every triangle of the mesh drawn into one canvas that counts its writes.
Canvas mesh_counts(DrawFunction draw, const std::vector<Triangle>& mesh, glm::ivec2 size) {
  Canvas canvas(size.x, size.y);
  canvas.enable_write_counts();
  for (const Triangle& t : mesh) draw(canvas, t, palette::black);
  return canvas;
}

int pixels_drawn_more_than_once(const Canvas& counted) {
  int pixels = 0;
  for (int y = 0; y < counted.height(); ++y) {
    for (int x = 0; x < counted.width(); ++x) pixels += counted.write_count(x, y) > 1;
  }
  return pixels;
}

// A count map: each pixel of the canvas filled by how often it was drawn, and the legend of the
// four categories.
PixelDiagram count_diagram(const Canvas& counted, std::string title, double cell) {
  PixelDiagram diagram({0, 0}, {counted.width() - 1, counted.height() - 1}, std::move(title), cell);
  for (int y = 0; y < counted.height(); ++y) {
    for (int x = 0; x < counted.width(); ++x) {
      const auto n = counted.write_count(x, y);
      if (n == 1) diagram.fill({x, y}, drawn_once);
      if (n == 2) diagram.fill({x, y}, drawn_twice);
      if (n >= 3) diagram.fill({x, y}, drawn_more);
    }
  }
  diagram.legend_fill("drawn 0 times", palette::empty);
  diagram.legend_fill("once", drawn_once);
  diagram.legend_fill("twice", drawn_twice);
  diagram.legend_fill("3 or more times", drawn_more);
  return diagram;
}

// The mesh's edges over a count map of a size x size canvas, cut at the canvas's border.
void draw_mesh_edges(PixelDiagram& diagram, const std::vector<Triangle>& mesh, int size) {
  for (const Triangle& t : mesh) {
    for (int i = 0; i < 3; ++i) {
      if (const auto part =
              tri::clip_segment(t[i], t[(i + 1) % 3], glm::dvec2(-0.5), glm::dvec2(size - 0.5))) {
        diagram.line((*part)[0], (*part)[1], palette::black, 1);
      }
    }
  }
}

// ---------------------------------------------------------------------------------------------
// The tie rule alone: a mesh whose vertices are pixel centres, drawn by the same rasterizer with
// and without the tie rule.

constexpr int integer_mesh_size = 23;

// A 5x5 grid of cells 4 pixels wide from (1,1) to (21,21), inner vertices moved by -1, 0 or 1
// pixel (so edges of many slopes pass through centres, or not), two triangles a cell.
std::vector<Triangle> integer_mesh() {
  tri::Random random(11);
  constexpr int columns = 5, rows = 5, step = 4;
  std::vector<glm::dvec2> points;
  for (int j = 0; j <= rows; ++j) {
    for (int i = 0; i <= columns; ++i) {
      const bool border = i == 0 || j == 0 || i == columns || j == rows;
      const int jx = border ? 0 : random.integer(-1, 1);
      const int jy = border ? 0 : random.integer(-1, 1);
      points.emplace_back(1 + i * step + jx, 1 + j * step + jy);
    }
  }
  const auto at = [&](int i, int j) {
    return points[static_cast<std::size_t>(j * (columns + 1) + i)];
  };
  std::vector<Triangle> mesh;
  for (int j = 0; j < rows; ++j) {
    for (int i = 0; i < columns; ++i) {
      // Alternate the diagonal, so each inner vertex is shared by four or eight triangles.
      if ((i + j) % 2 == 0) {
        mesh.push_back({{at(i, j), at(i + 1, j), at(i + 1, j + 1)}});
        mesh.push_back({{at(i, j), at(i + 1, j + 1), at(i, j + 1)}});
      } else {
        mesh.push_back({{at(i, j), at(i + 1, j), at(i, j + 1)}});
        mesh.push_back({{at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)}});
      }
    }
  }
  return mesh;
}

PixelDiagram integer_mesh_panel(DrawFunction draw, const std::string& rule,
                                const std::string& note) {
  const std::vector<Triangle> mesh = integer_mesh();
  const Canvas counted = mesh_counts(draw, mesh, {integer_mesh_size, integer_mesh_size});
  PixelDiagram diagram =
      count_diagram(counted,
                    rule + ": " + std::to_string(pixels_drawn_more_than_once(counted)) +
                        " pixels drawn more than once",
                    18);
  draw_mesh_edges(diagram, mesh, integer_mesh_size);
  diagram.legend_line("mesh edges (vertices on pixel centres)", palette::black);
  diagram.legend_note(note);
  return diagram;
}

std::string integer_mesh_figure() {
  const std::array<PixelDiagram, 2> panels{
      integer_mesh_panel(tri::ch07::draw_triangle_fixed_point_inclusive, "Inclusive rule",
                         "Inside, a vertex is drawn by all 4 or 8 triangles around it."),
      integer_mesh_panel(tri::ch07::draw_triangle_fixed_point_8, "Top-left rule",
                         "The mesh's own bottom and right border is not drawn."),
  };
  return tri::side_by_side(panels,
                           "A mesh with its vertices on pixel centres, drawn without and with "
                           "the tie rule: every doubled pixel disappears");
}

// ---------------------------------------------------------------------------------------------
// Snapping: a mesh with vertices off the pixel grid, drawn by chapter 06 (vertices rounded to
// pixel centres first) and by the fixed-point rasterizer (vertices kept to 1/256).

constexpr int jittered_mesh_size = 48;

// A 6x6 grid of cells over the canvas and 4 pixels beyond, vertices jittered on the 1/256 grid.
std::vector<Triangle> jittered_mesh() {
  return tri::ch07::jittered_mesh(6, 6, {-4, -4}, (jittered_mesh_size + 8.0) / 6, 0.15, 7);
}

// The mesh as chapter 06 draws it: every vertex rounded to its nearest pixel centre.
std::vector<Triangle> rounded_to_pixel_centres(std::vector<Triangle> mesh) {
  for (Triangle& t : mesh) {
    for (glm::dvec2& v : t) v = glm::dvec2(tri::nearest_pixel(v));
  }
  return mesh;
}

constexpr glm::ivec2 jittered_canvas{jittered_mesh_size, jittered_mesh_size};

std::string jittered_barycentric_figure() {
  const std::vector<Triangle> mesh = jittered_mesh();
  const Canvas counted = mesh_counts(draw_barycentric, mesh, jittered_canvas);
  PixelDiagram diagram = count_diagram(
      counted,
      "Chapter 06 on a jittered mesh: " + std::to_string(pixels_drawn_more_than_once(counted)) +
          " pixels drawn twice or more",
      10);
  draw_mesh_edges(diagram, rounded_to_pixel_centres(mesh), jittered_mesh_size);
  diagram.legend_line("edges after rounding each vertex to a pixel centre", palette::black);
  return diagram.svg();
}

std::string jittered_fixed_point_figure() {
  const std::vector<Triangle> mesh = jittered_mesh();
  const Canvas counted = mesh_counts(tri::ch07::draw_triangle_fixed_point_8, mesh, jittered_canvas);
  const Canvas inclusive =
      mesh_counts(tri::ch07::draw_triangle_fixed_point_inclusive, mesh, jittered_canvas);
  int changed = 0;
  for (int y = 0; y < jittered_mesh_size; ++y) {
    for (int x = 0; x < jittered_mesh_size; ++x) {
      changed += counted.write_count(x, y) != inclusive.write_count(x, y);
    }
  }
  PixelDiagram diagram = count_diagram(counted,
                                       "Fixed point on the same mesh, vertices kept to 1/256: " +
                                           std::to_string(pixels_drawn_more_than_once(counted)) +
                                           " pixels drawn more than once",
                                       10);
  draw_mesh_edges(diagram, mesh, jittered_mesh_size);
  diagram.legend_line("mesh edges (vertices on the 1/256 grid)", palette::black);
  diagram.legend_note("No pixel centre lies on an edge here: the inclusive rule changes " +
                      std::to_string(changed) + " pixels.");
  diagram.legend_note("Chapter 06 has ties here only because it rounds vertices to pixel centres.");
  return diagram.svg();
}

// ---------------------------------------------------------------------------------------------
// Two triangles sharing the edge (2,2)-(14,10), which passes through the centres (5,4), (8,6) and
// (11,8).

const Triangle upper{{{2, 2}, {14, 10}, {2, 11}}};
const Triangle lower{{{14, 10}, {2, 2}, {15, 1}}};
constexpr Color upper_color = palette::orange;
constexpr Color lower_color = palette::sky_blue;
constexpr Color both_color = palette::vermillion;

// The two triangles drawn separately, their pixels filled by who drew them (hatched where both
// did), rings on the centres of the shared edge, both vertices' coordinates.
PixelDiagram shared_edge_diagram(DrawFunction draw, std::string title) {
  Canvas upper_pixels(17, 13), lower_pixels(17, 13);
  upper_pixels.enable_write_counts();
  lower_pixels.enable_write_counts();
  draw(upper_pixels, upper, palette::black);
  draw(lower_pixels, lower, palette::black);
  PixelDiagram diagram({0, 0}, {16, 12}, std::move(title), 28);
  int drawn_by_both = 0;
  for (int y = 0; y <= 12; ++y) {
    for (int x = 0; x <= 16; ++x) {
      const bool u = upper_pixels.write_count(x, y) > 0, l = lower_pixels.write_count(x, y) > 0;
      if (u && l) {
        ++drawn_by_both;
        diagram.fill({x, y}, both_color);
        diagram.mark({x, y}, PixelMark::hatch, palette::empty);
      } else if (u || l) {
        diagram.fill({x, y}, u ? upper_color : lower_color);
      }
      if (centre_on_segment(upper[0], upper[1], {x, y})) diagram.mark({x, y}, PixelMark::ring);
    }
  }
  diagram.triangle(upper[0], upper[1], upper[2], palette::black, 1.5);
  diagram.triangle(lower[0], lower[1], lower[2], palette::black, 1.5);
  vertex_label(diagram, {2, 2}, LabelPlace::below_left);
  vertex_label(diagram, {14, 10}, LabelPlace::above_right);
  vertex_label(diagram, {2, 11}, LabelPlace::above_right);
  vertex_label(diagram, {15, 1}, LabelPlace::below_left);
  diagram.legend_fill("upper triangle only", upper_color);
  diagram.legend_fill("lower triangle only", lower_color);
  diagram.legend_fill(drawn_by_both == 0 ? "drawn by both (none)" : "drawn by both", both_color);
  diagram.legend_mark("centre on the shared edge", PixelMark::ring);
  return diagram;
}

std::string shared_edge_inclusive_figure() {
  return shared_edge_diagram(draw_edge_function,
                             "Chapter 05's inclusive test: both triangles draw the shared edge")
      .svg();
}

// The same pair by the top-left rule, with the class of the shared edge named on each side.
std::string shared_edge_top_left_figure() {
  PixelDiagram diagram =
      shared_edge_diagram(tri::ch07::draw_triangle_fixed_point_8,
                          "Top-left rule: the shared edge belongs to the lower triangle alone");
  diagram.label({7.2, 7.2}, "right edge of the upper triangle", LabelPlace::left);
  diagram.label({8.6, 4.9}, "left edge of the lower triangle", LabelPlace::right);
  diagram.legend_note("(2, 2) goes to the lower triangle: both of its edges there are left edges.");
  diagram.legend_note("(14, 10) goes to neither: each triangle has a right edge through it.");
  return diagram.svg();
}

}  // namespace

int main(int argc, char** argv) {
  return tri::run_chapter_program(
      argc, argv, "07_exact_coverage",
      "Chapter 07, exact coverage: six pixel diagrams (SVG).\n"
      "  07_top_left_rule: six triangles around a shared vertex, each edge coloured by its class\n"
      "    (top, left or other); every centre on an edge is ringed, its pixel in the colour of\n"
      "    the triangle that owns it (white: none).\n"
      "  07_mesh_counts_ties: a mesh with its vertices on pixel centres, drawn by the fixed-point\n"
      "    rasterizer without the tie rule (inclusive) and with it (top-left).\n"
      "  07_mesh_counts_barycentric, 07_mesh_counts_fixed_point: a jittered mesh drawn by\n"
      "    chapter 06 (vertices rounded to pixel centres) and by the fixed-point rasterizer.\n"
      "  The three count maps: white = drawn 0 times, light grey = once, orange = twice,\n"
      "    blue = 3 or more times.\n"
      "  07_shared_edge_inclusive, 07_shared_edge_top_left: two triangles sharing an edge\n"
      "    through pixel centres, drawn by chapter 05's inclusive test and by the top-left rule\n"
      "    (orange = upper only, sky blue = lower only, hatched vermillion = drawn by both).",
      [](tri::FigureWriter& figures) {
        figures.save_svg("07_top_left_rule", top_left_rule_figure());
        figures.save_svg("07_mesh_counts_ties", integer_mesh_figure());
        figures.save_svg("07_mesh_counts_barycentric", jittered_barycentric_figure());
        figures.save_svg("07_mesh_counts_fixed_point", jittered_fixed_point_figure());
        figures.save_svg("07_shared_edge_inclusive", shared_edge_inclusive_figure());
        figures.save_svg("07_shared_edge_top_left", shared_edge_top_left_figure());
      });
}
