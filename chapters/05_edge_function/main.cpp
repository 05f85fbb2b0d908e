// Chapter 05's figures: the tinyrenderer triangles filled by the edge-function test, the signs of
// the three edge values, the bounding box (and its clamping), the published bug, zero-area cases.
// Each one that argues about pixels is a pixel diagram (common/pixel_diagram.hpp).
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "chapters/01_lines/lines.hpp"
#include "chapters/02_wireframe/example_triangles.hpp"
#include "chapters/02_wireframe/tinyrenderer_figure.hpp"
#include "chapters/05_edge_function/bounding_box.hpp"
#include "chapters/05_edge_function/cross_product.hpp"
#include "chapters/05_edge_function/edge_function_fill.hpp"
#include "chapters/05_edge_function/point_in_triangle.hpp"
#include "common/figures.hpp"
#include "common/pixel_diagram.hpp"

namespace {

using namespace tri;
using tri::ch02::label_vertices;
namespace dc = tri::diagram_colors;
using Vertices = std::array<glm::ivec2, 3>;

// Okabe–Ito colours lightened towards white, for fills under black text and dots.
constexpr Color light_green{153, 216, 199, 255};
constexpr Color light_sky{187, 225, 246, 255};
constexpr Color light_vermillion{242, 191, 153, 255};
constexpr Color light_blue{153, 199, 224, 255};
constexpr Color light_purple{235, 201, 220, 255};
// Paints the pixel sets the figures compute on a (black) canvas before they are coloured.
constexpr Color marked = tri::colors::white;

using tri::ch02::tinyrenderer_triangles;
// The pixels of the published-bug zoom: the third triangle and its surroundings.
constexpr glm::ivec2 zoom_first{116, 147}, zoom_last{182, 182};

glm::dvec2 at(glm::ivec2 p) {
  return glm::dvec2(p);
}

// Step 4: tinyrenderer's three triangles, a whole scene, with their ideal edges on top.
tri::SvgFigure tinyrenderer_figure() {
  const PixelDiagram d = tri::ch02::tinyrenderer_fill_diagram(
      "tinyrenderer's three triangles filled by the edge-function test (200 x 200)",
      tri::ch05::fill_triangle_edge_function);
  return tri::SvgFigure{"05_tinyrenderer_triangles", d.svg()};
}

// Step 2: every pixel centre coloured by the signs of its three edge values: which of them are
// negative says on which side of which edge it lies.
tri::SvgFigure edge_signs_figure() {
  const glm::ivec2 a(1, 1), b(13, 4), c(5, 10);
  PixelDiagram d({0, 0}, {14, 11}, "The signs of AB x AP, BC x BP, CA x CP at every pixel centre P",
                 32);
  const std::array<Color, 3> one_negative{light_vermillion, light_blue, light_purple};
  int on_edge = 0;
  for (int y = 0; y <= 11; ++y) {
    for (int x = 0; x <= 14; ++x) {
      const glm::i64vec3 e = tri::ch05::edge_crosses(a, b, c, {x, y});
      const int negatives = (e.x < 0) + (e.y < 0) + (e.z < 0);
      if (negatives == 0 && (e.x == 0 || e.y == 0 || e.z == 0)) {
        d.fill({x, y}, dc::yellow);
        d.mark({x, y}, PixelMark::square, dc::black);
        ++on_edge;
      } else if (negatives == 0) {
        d.fill({x, y}, light_green);
      } else if (negatives == 1) {
        d.fill({x, y}, one_negative[e.x < 0 ? 0 : e.y < 0 ? 1 : 2]);
      } else {
        d.fill({x, y}, dc::light_gray);
      }
    }
  }
  d.line(at(a), at(b), dc::vermillion);
  d.line(at(b), at(c), dc::blue);
  d.line(at(c), at(a), dc::purple);
  label_vertices(d, {a, b, c},
                 {LabelPlace::below_right, LabelPlace::below_right, LabelPlace::above_right});
  d.legend_fill("all three > 0: inside", light_green);
  d.legend_fill("all >= 0, one is 0: on an edge", dc::yellow);
  d.legend_mark("centre exactly on an edge (drawn)", PixelMark::square);
  d.legend_fill("AB x AP < 0 only", light_vermillion);
  d.legend_fill("BC x BP < 0 only", light_blue);
  d.legend_fill("CA x CP < 0 only", light_purple);
  d.legend_fill("two values < 0 (past a vertex)", dc::light_gray);
  d.legend_line("edge AB", dc::vermillion);
  d.legend_line("edge BC", dc::blue);
  d.legend_line("edge CA", dc::purple);
  d.legend_note("A, B, C run counter-clockwise; " + std::to_string(on_edge) +
                " centres lie exactly on an edge (A, B, C among them).");
  return tri::SvgFigure{"05_edge_signs", d.svg()};
}

// Step 1: the box the loop visits (clamped to the canvas), the pixels drawn, the vertices. The
// diagram shows `shown` pixels, which may reach beyond the canvas to show the whole triangle.
tri::SvgFigure bounding_box_figure(std::string name, const std::string& title, const Vertices& v,
                                   glm::ivec2 canvas_size, glm::ivec2 shown_first,
                                   glm::ivec2 shown_last) {
  Canvas canvas(canvas_size.x, canvas_size.y);
  tri::ch05::fill_triangle_edge_function(canvas, v[0], v[1], v[2], dc::blue);
  const auto box =
      tri::ch05::bounding_box_on_canvas(v[0], v[1], v[2], canvas_size.x, canvas_size.y);
  PixelDiagram d(shown_first, shown_last, title, 14);
  bool off_canvas = false;
  for (int y = shown_first.y; y <= shown_last.y; ++y) {
    for (int x = shown_first.x; x <= shown_last.x; ++x) {
      if (x < 0 || y < 0 || x >= canvas_size.x || y >= canvas_size.y) {
        d.fill({x, y}, dc::light_gray);
        off_canvas = true;
      } else if (canvas.pixel(x, y) == dc::blue) {
        d.fill({x, y}, dc::blue);
      } else if (x >= box.min.x && x <= box.max.x && y >= box.min.y && y <= box.max.y) {
        d.fill({x, y}, light_sky);
      }
    }
  }
  d.triangle(at(v[0]), at(v[1]), at(v[2]), dc::black);
  label_vertices(d, v, {LabelPlace::left, LabelPlace::below_right, LabelPlace::above_right});
  for (const glm::ivec2 p : v) {
    if (canvas.contains(p)) d.mark(p, PixelMark::square, dc::vermillion);
  }
  d.legend_fill("in the box, tested, outside the triangle", light_sky);
  d.legend_fill("in the box, drawn", dc::blue);
  if (off_canvas) d.legend_fill("off the canvas: never visited", dc::light_gray);
  d.legend_mark("a vertex's pixel", PixelMark::square, dc::vermillion);
  d.legend_line("ideal triangle", dc::black);
  d.legend_note("Box: columns " + std::to_string(box.min.x) + " to " + std::to_string(box.max.x) +
                ", rows " + std::to_string(box.min.y) + " to " + std::to_string(box.max.y) +
                " (both ends included).");
  return tri::SvgFigure{std::move(name), d.svg()};
}

// The published test against the right one, as three pixel sets on one canvas.
struct BugComparison {
  Canvas both{200, 200}, lost{200, 200}, extra{200, 200};
};

BugComparison compare_published_bug() {
  Canvas right(200, 200), published(200, 200);
  for (const auto& triangle : tinyrenderer_triangles) {
    const auto& [a, b, c] = triangle.vertices;
    tri::ch05::fill_triangle_edge_function(right, a, b, c, marked);
    tri::ch05::fill_triangle_published_bug(published, a, b, c, marked);
  }
  BugComparison out;
  for (int y = 0; y < 200; ++y) {
    for (int x = 0; x < 200; ++x) {
      const bool r = right.pixel(x, y) == marked, p = published.pixel(x, y) == marked;
      if (r && p) out.both.put_pixel(x, y, marked);
      if (r && !p) out.lost.put_pixel(x, y, marked);
      if (!r && p) out.extra.put_pixel(x, y, marked);
    }
  }
  return out;
}

// The lines the published test really uses for BC and CA: each slid vertically to A's height,
// drawn across the shown pixels.
void draw_slid_lines(PixelDiagram& d, const Vertices& v, Color color) {
  const glm::dvec2 a = at(v[0]), b = at(v[1]), c = at(v[2]);
  const glm::dvec2 bc_shift(0, a.y - b.y), ca_shift(0, a.y - c.y);
  const std::array<std::array<glm::dvec2, 2>, 2> lines{
      {{b + bc_shift, c + bc_shift}, {c + ca_shift, a + ca_shift}}};
  for (const auto& [p, q] : lines) {
    // Extended far beyond the edge's length, then cut to the diagram.
    d.line(p - 100.0 * (q - p), q + 100.0 * (q - p), color, 1.5, true);
  }
}

void fill_comparison(PixelDiagram& d, const BugComparison& cmp) {
  d.fill(painted_pixels(cmp.both, marked), dc::covered);
  d.fill(painted_pixels(cmp.lost, marked), light_sky);
  d.fill(painted_pixels(cmp.extra, marked), dc::vermillion);
}

tri::SvgFigure published_bug_figure() {
  const BugComparison cmp = compare_published_bug();
  PixelDiagram d({0, 0}, {199, 199}, "The published points[0].y test against the right one", 3);
  d.show_centres(false);
  fill_comparison(d, cmp);
  for (const auto& triangle : tinyrenderer_triangles) {
    const auto& [a, b, c] = triangle.vertices;
    d.triangle(at(a), at(b), at(c), dc::black, 1);
  }
  const glm::ivec2 first = zoom_first, last = zoom_last;
  d.line(glm::dvec2(first) - 0.5, glm::dvec2(last.x + 0.5, first.y - 0.5), dc::purple, 1.5);
  d.line(glm::dvec2(last) + 0.5, glm::dvec2(last.x + 0.5, first.y - 0.5), dc::purple, 1.5);
  d.line(glm::dvec2(last) + 0.5, glm::dvec2(first.x - 0.5, last.y + 0.5), dc::purple, 1.5);
  d.line(glm::dvec2(first) - 0.5, glm::dvec2(first.x - 0.5, last.y + 0.5), dc::purple, 1.5);
  d.legend_fill("drawn by both", dc::covered);
  d.legend_fill("inside, lost by the published test", light_sky);
  d.legend_fill("outside, drawn by the published test", dc::vermillion);
  d.legend_line("ideal triangles", dc::black);
  d.legend_line("region of the zoomed figure", dc::purple);
  return tri::SvgFigure{"05_published_bug", d.svg()};
}

// The zoomed companion: the third triangle, where the lost and the extra pixels sit side by side.
tri::SvgFigure published_bug_zoom_figure() {
  const BugComparison cmp = compare_published_bug();
  const Vertices& v = tinyrenderer_triangles[2].vertices;
  PixelDiagram d(zoom_first, zoom_last,
                 "Zoom on the third triangle: the published test tests against slid edges", 12);
  fill_comparison(d, cmp);
  for (const auto p : painted_pixels(cmp.extra, marked)) d.mark(p, PixelMark::cross, dc::black);
  for (const auto p : painted_pixels(cmp.both, marked)) d.mark(p, PixelMark::square, dc::black);
  d.triangle(at(v[0]), at(v[1]), at(v[2]), dc::black);
  draw_slid_lines(d, v, dc::purple);
  label_vertices(d, v, {LabelPlace::below_left, LabelPlace::right, LabelPlace::right});
  d.legend_fill("inside, lost by the published test", light_sky);
  d.legend_fill("drawn by the published test only", dc::vermillion);
  d.legend_mark("outside the triangle, drawn", PixelMark::cross);
  d.legend_mark("drawn by both (grey, outlined)", PixelMark::square);
  d.legend_line("ideal triangle", dc::black);
  d.legend_line("BC and CA slid to A's height: what the published test tests against", dc::purple,
                true);
  return tri::SvgFigure{"05_published_bug_zoom", d.svg()};
}

// Zero-area triangles: the ideal segment, chapter 01's Bresenham line under it for comparison,
// and the pixels the fill draws: only the centres exactly on the segment.
tri::SvgFigure zero_area_figure() {
  const std::array<Vertices, 3> segments{{
      {{{0, 0}, {10, 10}, {20, 20}}},
      {{{2, 22}, {12, 25}, {22, 28}}},
      {{{20, 4}, {20, 4}, {20, 4}}},
  }};
  Canvas bresenham(24, 30), drawn(24, 30);
  for (const auto& [a, b, c] : segments) {
    tri::ch01::draw_line_bresenham(bresenham, a, c, marked);
    tri::ch05::fill_triangle_edge_function(drawn, a, b, c, marked);
  }
  PixelDiagram d({0, 0}, {23, 29}, "Zero-area triangles draw only the centres on their segment",
                 18);
  d.fill(painted_pixels(bresenham, marked), dc::light_gray);
  d.fill(painted_pixels(drawn, marked), dc::sky_blue);
  for (const auto& [a, b, c] : segments) d.line(at(a), at(c), dc::vermillion);
  label_vertices(d, segments[0],
                 {LabelPlace::above_right, LabelPlace::below_right, LabelPlace::above_left});
  label_vertices(d, segments[1],
                 {LabelPlace::below_right, LabelPlace::below_right, LabelPlace::below_left});
  d.vertex(at(segments[2][0]), "A = B = C", LabelPlace::above_left);
  d.legend_fill("drawn by the fill", dc::sky_blue);
  d.legend_fill("chapter 01's Bresenham line, not drawn by the fill", dc::light_gray);
  d.legend_line("the ideal segment", dc::vermillion);
  d.legend_note(
      "Direction (1, 1): every centre on it; (10, 3): only A, B, C; one point: one pixel.");
  return tri::SvgFigure{"05_zero_area", d.svg()};
}

}  // namespace

int main(int argc, char** argv) {
  return tri::run_chapter_program(
      argc, argv, "05_edge_function",
      "Chapter 05, the edge-function fill: edge signs, bounding boxes, the published bug.",
      {tinyrenderer_figure, edge_signs_figure,
       [] {
         return bounding_box_figure("05_bounding_box",
                                    "The bounding box: every pixel in it is tested",
                                    {{{5, 4}, {34, 11}, {14, 27}}}, {40, 32}, {0, 0}, {39, 31});
       },
       [] {
         return bounding_box_figure(
             "05_bounding_box_clamped", "The box cut down to the 40 x 32 canvas",
             {{{-12, 6}, {24, -9}, {30, 26}}}, {40, 32}, {-17, -10}, {39, 31});
       },
       published_bug_figure, published_bug_zoom_figure, zero_area_figure});
}
