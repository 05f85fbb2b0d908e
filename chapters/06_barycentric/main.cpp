// Chapter 06's figures: tinyrenderer's three triangles with their bounding boxes, filled, and
// coloured by their barycentric weights; what a zero area draws without the guard; and where
// float and double part ways. Each one that argues about pixels is a pixel diagram.
#include <array>
#include <string>
#include <vector>

#include "chapters/02_wireframe/example_triangles.hpp"
#include "chapters/02_wireframe/tinyrenderer_figure.hpp"
#include "chapters/05_edge_function/bounding_box.hpp"
#include "chapters/06_barycentric/barycentric.hpp"
#include "chapters/06_barycentric/examples.hpp"
#include "chapters/06_barycentric/fill.hpp"
#include "common/figures.hpp"
#include "common/pixel_diagram.hpp"

namespace {

using namespace tri;
using namespace tri::ch02;
using tri::ch06::PixelTriangle;
namespace dc = tri::diagram_colors;

// The same three, lightened towards white: the tested part of each bounding box.
constexpr std::array<Color, 3> box_colors{Color{242, 191, 153, 255}, Color{153, 199, 224, 255},
                                          Color{153, 216, 199, 255}};
// Paints the pixel sets the figures compute on a (black) canvas before they are coloured.
constexpr Color marked = tri::colors::white;

glm::dvec2 at(glm::ivec2 p) {
  return glm::dvec2(p);
}

// The pixels of a clamped bounding box.
std::vector<glm::ivec2> box_pixels(const PixelTriangle& t, int width, int height) {
  const auto box = tri::ch05::bounding_box_on_canvas(t[0], t[1], t[2], width, height);
  std::vector<glm::ivec2> out;
  for (int y = box.min.y; y <= box.max.y; ++y) {
    for (int x = box.min.x; x <= box.max.x; ++x) out.emplace_back(x, y);
  }
  return out;
}

// Step 1: each triangle over its bounding box, the pixels the loop visits.
tri::SvgFigure bounding_boxes_figure() {
  PixelDiagram d =
      tinyrenderer_scene_diagram("Every pixel of each bounding box is tested; few are drawn");
  Canvas drawn(200, 200);
  for (std::size_t i = 0; i < 3; ++i) {
    const auto [a, b, c] = tinyrenderer_triangles[i].vertices;
    tri::ch06::fill_triangle_barycentric<double>(drawn, a, b, c, tinyrenderer_figure_colors[i]);
  }
  for (std::size_t i = 0; i < 3; ++i) {
    const auto& t = tinyrenderer_triangles[i].vertices;
    const auto box = box_pixels(t, 200, 200);
    d.fill(box, box_colors[i]);
    d.legend_fill(std::string(tinyrenderer_names[i]) + " box: " + std::to_string(box.size()) +
                      " pixels tested",
                  box_colors[i]);
    d.legend_fill(std::string(tinyrenderer_names[i]) + " triangle: " +
                      std::to_string(painted_pixels(drawn, tinyrenderer_figure_colors[i]).size()) +
                      " drawn",
                  tinyrenderer_figure_colors[i]);
  }
  d.fill_from(drawn, tri::colors::black);
  for (const auto& triangle : tinyrenderer_triangles) {
    const auto& [a, b, c] = triangle.vertices;
    d.triangle(at(a), at(b), at(c), dc::black, 1);
  }
  d.legend_line("ideal triangle edges", dc::black);
  return tri::SvgFigure{"06_bounding_boxes", d.svg()};
}

// Step 4: the three triangles filled, as tinyrenderer shows them.
tri::SvgFigure tinyrenderer_figure() {
  const PixelDiagram d = tri::ch02::tinyrenderer_fill_diagram(
      "tinyrenderer's three triangles filled by barycentric weights",
      tri::ch06::fill_triangle_barycentric<double>);
  return tri::SvgFigure{"06_tinyrenderer_triangles", d.svg()};
}

// Step 5: the same triangles, each pixel a blend of red, green and blue by its weights.
tri::SvgFigure weights_figure() {
  PixelDiagram d = tinyrenderer_scene_diagram("Each pixel coloured wA red + wB green + wC blue");
  Canvas canvas(200, 200);
  for (const auto& triangle : tinyrenderer_triangles) {
    const auto& [a, b, c] = triangle.vertices;
    tri::ch06::fill_triangle_with_weights(canvas, a, b, c, tri::colors::red, tri::colors::green,
                                          tri::colors::blue);
  }
  // 16 levels per channel (multiples of 17) merge neighbouring pixels into runs: the SVG stays
  // a quarter of its size, and the blend still reads.
  for (int y = 0; y < canvas.height(); ++y) {
    for (int x = 0; x < canvas.width(); ++x) {
      const Color c = canvas.pixel(x, y);
      const auto level = [](int v) { return static_cast<std::uint8_t>((v + 8) / 17 * 17); };
      canvas.put_pixel(x, y, Color{level(c.r), level(c.g), level(c.b), 255});
    }
  }
  d.fill_from(canvas, tri::colors::black);
  for (const auto& triangle : tinyrenderer_triangles) {
    const auto& t = triangle.vertices;
    d.triangle(at(t[0]), at(t[1]), at(t[2]), dc::black, 1);
    const std::array<const char*, 3> names{"A", "B", "C"};
    for (std::size_t k = 0; k < 3; ++k) {
      d.point(at(t[k]), dc::black, 3);
      d.label(at(t[k]), names[k], LabelPlace::right);
    }
  }
  d.legend_fill("A, the first vertex: weight (1, 0, 0)", tri::colors::red);
  d.legend_fill("B: (0, 1, 0)", tri::colors::green);
  d.legend_fill("C: (0, 0, 1)", tri::colors::blue);
  d.legend_line("ideal triangle edges", dc::black);
  d.legend_note(
      "In between, the colours mix in proportion to the three weights (shown in 16 "
      "levels per channel).");
  return tri::SvgFigure{"06_barycentric_weights", d.svg()};
}

// Step 3: zero-area triangles without the guard: the box the loop visits, what the NaN weights
// let through, the ideal segment. The guarded version draws nothing here.
tri::SvgFigure zero_area_unguarded_figure() {
  const std::array<PixelTriangle, 4> degenerate{{
      {{{1, 1}, {3, 2}, {9, 5}}},     // diagonal, direction (2, 1)
      {{{1, 8}, {10, 8}, {5, 8}}},    // horizontal
      {{{2, 10}, {2, 10}, {9, 11}}},  // two vertices equal, no pixel centre between the ends
      {{{10, 1}, {10, 1}, {10, 1}}},  // a point
  }};
  Canvas unguarded(12, 13), guarded(12, 13);
  PixelDiagram d({0, 0}, {11, 12}, "Without the guard, NaN weights draw the centres on the segment",
                 32);
  for (const auto& t : degenerate) {
    d.fill(box_pixels(t, 12, 13), dc::light_gray);
    tri::ch06::fill_triangle_barycentric_unguarded<double>(unguarded, t[0], t[1], t[2], marked);
    tri::ch06::fill_triangle_barycentric<double>(guarded, t[0], t[1], t[2], marked);
  }
  const auto drawn = painted_pixels(unguarded, marked);
  d.fill(drawn, dc::vermillion);
  for (const auto p : drawn) d.mark(p, PixelMark::ring, dc::black);
  for (const auto& t : degenerate) {
    // The segment is the hull of the three points: from the lowest to the highest in (x, y).
    glm::ivec2 low = t[0], high = t[0];
    for (const auto p : t) {
      if (p.x < low.x || (p.x == low.x && p.y < low.y)) low = p;
      if (p.x > high.x || (p.x == high.x && p.y > high.y)) high = p;
    }
    d.line(at(low), at(high), dc::blue);
  }
  label_vertices(d, degenerate[0],
                 {LabelPlace::above_left, LabelPlace::above_left, LabelPlace::above_left});
  label_vertices(d, degenerate[1],
                 {LabelPlace::above_right, LabelPlace::above_left, LabelPlace::above_right});
  d.vertex(at(degenerate[2][0]), "A = B", LabelPlace::above_right);
  d.vertex(at(degenerate[2][2]), "C", LabelPlace::above_left);
  d.vertex(at(degenerate[3][0]), "A = B = C", LabelPlace::above_left);
  d.legend_fill("in a bounding box: tested", dc::light_gray);
  d.legend_fill("drawn without the guard", dc::vermillion);
  d.legend_mark("NaN weights: centre on the segment", PixelMark::ring);
  d.legend_line("the ideal segment (zero area)", dc::blue);
  d.legend_note("Without the guard: " + std::to_string(drawn.size()) +
                " pixels drawn. With the guard: " +
                std::to_string(painted_pixels(guarded, marked).size()) + ".");
  return tri::SvgFigure{"06_zero_area_unguarded", d.svg()};
}

// The guarded fill of t in float and in double, each in `marked` on a size x size canvas.
struct FloatAndDouble {
  Canvas with_float, with_double;
};

FloatAndDouble filled_in_float_and_double(const PixelTriangle& t, int size) {
  FloatAndDouble out{Canvas(size, size), Canvas(size, size)};
  tri::ch06::fill_triangle_barycentric<float>(out.with_float, t[0], t[1], t[2], marked);
  tri::ch06::fill_triangle_barycentric<double>(out.with_double, t[0], t[1], t[2], marked);
  return out;
}

// The kept triangle of the seeded search, on its 16x16 canvas: where float and double agree, and
// the one pixel centre on edge BC that only double draws. The vertices are 10^4 pixels away, so
// their true coordinates go in the legend and the edges are cut to the canvas.
tri::SvgFigure float_versus_double_figure() {
  const PixelTriangle& t = tri::ch06::float_double_disagreement;
  const auto [with_float, with_double] = filled_in_float_and_double(t, 16);
  const glm::ivec2 first(0, 0), last(15, 15);
  PixelDiagram d(first, last, "float and double disagree on one centre exactly on edge BC", 32);
  std::vector<glm::ivec2> both, double_only, float_only;
  for (int y = 0; y < 16; ++y) {
    for (int x = 0; x < 16; ++x) {
      const bool f = with_float.pixel(x, y) == marked, dbl = with_double.pixel(x, y) == marked;
      if (f && dbl) both.emplace_back(x, y);
      if (dbl && !f) double_only.emplace_back(x, y);
      if (f && !dbl) float_only.emplace_back(x, y);
    }
  }
  d.fill(both, dc::covered);
  d.fill(double_only, dc::vermillion);
  d.fill(float_only, dc::sky_blue);
  for (const auto p : double_only) d.mark(p, PixelMark::ring);
  for (const auto p : float_only) d.mark(p, PixelMark::cross);
  const std::array<Color, 3> edge_colors{dc::orange, dc::blue, dc::purple};
  const std::array<const char*, 3> edge_names{"AB", "BC", "CA"};
  for (std::size_t k = 0; k < 3; ++k) {
    d.line(at(t[k]), at(t[(k + 1) % 3]), edge_colors[k], 2);
  }
  for (const auto p : double_only) {
    d.label(at(p), "midpoint of BC " + point_text(p), LabelPlace::below_left);
  }
  d.legend_fill("drawn by both", dc::covered);
  d.legend_fill("drawn by double only", dc::vermillion);
  d.legend_mark("float rounds wA below 0 here", PixelMark::ring);
  if (!float_only.empty()) d.legend_fill("drawn by float only", dc::sky_blue);
  for (std::size_t k = 0; k < 3; ++k) {
    if (tri::clip_to_pixels(at(t[k]), at(t[(k + 1) % 3]), first, last)) {
      d.legend_line(std::string("edge ") + edge_names[k], edge_colors[k]);
    }
  }
  d.legend_note("Vertices far off this 16 x 16 canvas: A " + point_text(t[0]) + ", B " +
                point_text(t[1]) + ", C " + point_text(t[2]) + ".");
  d.legend_note("double draws " + std::to_string(both.size() + double_only.size()) +
                " pixels (the exact set), float " +
                std::to_string(both.size() + float_only.size()) + ".");
  return tri::SvgFigure{"06_float_vs_double", d.svg()};
}

// A zero-area triangle 10^7 away, which double leaves empty and float draws because it computes
// the area as 2^21: the pixel centres float draws on the line and off it.
tri::SvgFigure float_zero_area_far_away_figure() {
  const PixelTriangle& t = tri::ch06::collinear_at_ten_million;
  const auto [with_float, with_double] = filled_in_float_and_double(t, 32);
  const glm::ivec2 first(0, 0), last(31, 31);
  PixelDiagram d(first, last, "float draws a zero-area triangle whose vertices are 10^7 away", 18);
  std::vector<glm::ivec2> on_line, off_line;
  for (const auto p : painted_pixels(with_float, marked)) {
    // On the line through the vertices exactly when the integer cross product is 0.
    const glm::i64vec2 u = glm::i64vec2(t[1]) - glm::i64vec2(t[0]);
    const glm::i64vec2 v = glm::i64vec2(p) - glm::i64vec2(t[0]);
    (u.x * v.y - u.y * v.x == 0 ? on_line : off_line).push_back(p);
  }
  d.fill(on_line, dc::sky_blue);
  d.fill(off_line, dc::vermillion);
  for (const auto p : on_line) d.mark(p, PixelMark::ring);
  for (const auto p : off_line) d.mark(p, PixelMark::cross);
  d.line(at(t[0]), at(t[1]), dc::blue, 2);
  d.vertex(at(t[2]), "C", LabelPlace::right);
  d.legend_fill("drawn by float, centre on the line", dc::sky_blue);
  d.legend_mark("on the line", PixelMark::ring);
  d.legend_fill("drawn by float, centre off the line", dc::vermillion);
  d.legend_mark("off the line", PixelMark::cross);
  d.legend_line("the line through A, B, C (zero area)", dc::blue);
  d.legend_note("A " + point_text(t[0]) + " and B " + point_text(t[1]) +
                " lie far off the canvas.");
  d.legend_note("float draws " + std::to_string(on_line.size() + off_line.size()) +
                " pixels, double " + std::to_string(painted_pixels(with_double, marked).size()) +
                ".");
  return tri::SvgFigure{"06_float_zero_area_far_away", d.svg()};
}

}  // namespace

int main(int argc, char** argv) {
  return tri::run_chapter_program(
      argc, argv, "06_barycentric",
      "Chapter 06, barycentric coordinates: weights, the zero-area guard, float and double.",
      {bounding_boxes_figure, tinyrenderer_figure, weights_figure, zero_area_unguarded_figure,
       float_versus_double_figure, float_zero_area_far_away_figure});
}
