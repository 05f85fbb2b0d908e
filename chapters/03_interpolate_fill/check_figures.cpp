#include "chapters/03_interpolate_fill/check_figures.hpp"

#include <array>
#include <cstdint>
#include <vector>

#include "chapters/02_wireframe/example_triangles.hpp"
#include "chapters/02_wireframe/wireframe.hpp"
#include "chapters/03_interpolate_fill/diagram_support.hpp"
#include "chapters/03_interpolate_fill/fill_steps.hpp"
#include "chapters/03_interpolate_fill/filled_triangle.hpp"
#include "common/canvas.hpp"
#include "common/centered_view.hpp"

namespace tri::ch03::figures {
namespace {

namespace dc = diagram_colors;
using Vertices = std::array<glm::ivec2, 3>;

constexpr Color fill_color = dc::sky_blue;
constexpr Color outline_in_fill = dc::dark_gray;
constexpr Color outline_outside = dc::vermillion;

// How many outline pixels a check painted, and how many of them lie outside the fill.
struct OutlineCount {
  int outline = 0;
  int outside = 0;
};

// Fills the triangle on `categories` (canvas coordinates), then paints chapter 02's outline on
// top: blue where the fill covers it, vermillion where it does not.
OutlineCount paint_fill_and_outline(Canvas& categories, const Vertices& v) {
  Canvas fill(categories.width(), categories.height());
  Canvas outline(categories.width(), categories.height());
  fill.enable_write_counts();
  outline.enable_write_counts();
  draw_filled_triangle(fill, v[0], v[1], v[2], dc::black);
  ch02::draw_wireframe_triangle(outline, v[0], v[1], v[2], dc::black);
  OutlineCount count;
  for (int y = 0; y < categories.height(); ++y) {
    for (int x = 0; x < categories.width(); ++x) {
      const bool filled = fill.write_count(x, y) > 0;
      if (filled) categories.put_pixel(x, y, fill_color);
      if (outline.write_count(x, y) == 0) continue;
      ++count.outline;
      if (!filled) ++count.outside;
      categories.put_pixel(x, y, filled ? outline_in_fill : outline_outside);
    }
  }
  return count;
}

// Figure 7-3's vertices in the book's centred coordinates, upside down for flip = -1.
Vertices figure_7_3_vertices(int flip) {
  Vertices v = tri::ch02::figure_7_1_triangle;
  for (glm::ivec2& p : v) p.y *= flip;
  return v;
}

constexpr int figure_size = tri::ch02::figure_7_1_canvas_size;
constexpr glm::ivec2 to_centred{-figure_size / 2, -figure_size / 2};

// The close-up's pixels on the wide edge P0-P1, in centred coordinates.
glm::ivec2 close_up_first(int flip) {
  return {-20, flip > 0 ? -117 : 102};
}
constexpr glm::ivec2 close_up_extent{15, 15};

void legend_categories(PixelDiagram& diagram) {
  diagram.legend_fill("fill", fill_color);
  diagram.legend_fill("outline pixel in the fill", outline_in_fill);
  diagram.legend_fill("outline pixel outside the fill", outline_outside);
}

std::string flip_name(int flip) {
  return flip > 0 ? "upright" : "flipped";
}

PixelDiagram close_up_panel(int flip) {
  const Vertices v = figure_7_3_vertices(flip);
  Canvas categories(figure_size, figure_size, dc::empty);
  tri::CenteredView view(categories);
  paint_fill_and_outline(categories,
                         {view.to_canvas(v[0]), view.to_canvas(v[1]), view.to_canvas(v[2])});
  const glm::ivec2 first = close_up_first(flip);
  PixelDiagram panel(first, first + close_up_extent, flip_name(flip), 24);
  panel.fill_from(categories, dc::empty, to_centred);
  panel.line(v[0], v[1], dc::black, 1.5);
  for (int x = first.x; x <= first.x + close_up_extent.x; ++x) {
    glm::ivec2 tie;
    if (halfway_tie(v[0], v[1], x, tie)) panel.mark(tie, PixelMark::ring);
    for (int y = first.y; y <= first.y + close_up_extent.y; ++y) {
      const glm::ivec2 on_canvas = view.to_canvas({x, y});
      if (categories.pixel(on_canvas.x, on_canvas.y) == outline_outside) {
        panel.mark({x, y}, PixelMark::cross, dc::black);
      }
    }
  }
  legend_categories(panel);
  panel.legend_mark("edge exactly halfway: y rounds up", PixelMark::ring);
  panel.legend_mark("outline outside the fill", PixelMark::cross);
  panel.legend_line("ideal edge P0-P1", dc::black);
  panel.legend_note("P0 (-200, " + std::to_string(v[0].y) + ") to P1 (200, " +
                    std::to_string(v[1].y) + "), triangle " + (flip > 0 ? "above" : "below"));
  return panel;
}

}  // namespace

SvgFigure figure_7_3(int flip) {
  const Vertices v = figure_7_3_vertices(flip);
  Canvas categories(figure_size, figure_size, dc::empty);
  tri::CenteredView view(categories);
  const OutlineCount count = paint_fill_and_outline(
      categories, {view.to_canvas(v[0]), view.to_canvas(v[1]), view.to_canvas(v[2])});
  PixelDiagram diagram({-210, -260}, {210, 260},
                       "Figure 7-3 " + flip_name(flip) + ": the outline drawn over the fill", 1);
  diagram.show_centres(false);
  diagram.fill_from(categories, dc::empty, to_centred);
  // Single pixels vanish at one unit per pixel: a dot on each outline pixel outside the fill.
  for (int y = 0; y < figure_size; ++y) {
    for (int x = 0; x < figure_size; ++x) {
      if (categories.pixel(x, y) == outline_outside) {
        diagram.point(glm::dvec2(glm::ivec2(x, y) + to_centred), outline_outside, 2.5);
      }
    }
  }
  const std::array<const char*, 3> names{"P0", "P1", "P2"};
  const std::array<LabelPlace, 3> places{LabelPlace::right, LabelPlace::left, LabelPlace::right};
  for (int i = 0; i < 3; ++i) diagram.vertex(v[i], names[i], places[i]);
  // The close-up's window, so the zoomed figure can be found here.
  const glm::ivec2 window = close_up_first(flip);
  diagram.frame(window, window + close_up_extent, dc::black);
  const glm::dvec2 lo = glm::dvec2(window) - 0.5, hi = glm::dvec2(window + close_up_extent) + 0.5;
  diagram.label({hi.x, flip > 0 ? lo.y : hi.y}, "close-up",
                flip > 0 ? LabelPlace::below_right : LabelPlace::above_right);
  legend_categories(diagram);
  diagram.legend_line("the close-up's pixels", dc::black);
  if (count.outside > 0)
    diagram.legend_note("Vermillion dots: the outline pixels outside the fill.");
  diagram.legend_note(std::to_string(count.outside) + " of the outline's " +
                      std::to_string(count.outline) + " pixels lie outside the fill.");
  return SvgFigure{flip > 0 ? "03_figure_7_3" : "03_figure_7_3_flipped", diagram.svg()};
}

SvgFigure figure_7_3_close_up() {
  const std::array<PixelDiagram, 2> panels{close_up_panel(1), close_up_panel(-1)};
  return SvgFigure{
      "03_figure_7_3_close_up",
      side_by_side(panels,
                   "Figure 7-3, the wide edge zoomed: its halfway ties round up, into the fill "
                   "upright, out of it flipped")};
}

SvgFigure tinyrenderer_fill_outline() {
  constexpr int size = tri::ch02::tinyrenderer_image_size;
  const auto& triangles = tri::ch02::tinyrenderer_triangles;
  Canvas categories(size, size, dc::empty);
  std::string counts;
  for (const auto& t : triangles) {
    counts += (counts.empty() ? "" : ", ") +
              std::to_string(paint_fill_and_outline(categories, t.vertices).outside);
  }
  PixelDiagram diagram({0, 0}, {size - 1, size - 1},
                       "tinyrenderer's triangles: the outline leaves the fill on wide edges", 3);
  diagram.show_centres(false);
  diagram.fill_from(categories, dc::empty);
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      if (categories.pixel(x, y) == outline_outside) diagram.point({x, y}, outline_outside, 2);
    }
  }
  const std::array<const char*, 3> names{"red", "white", "green"};
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    const auto& t = triangles[i].vertices;
    diagram.triangle(t[0], t[1], t[2], dc::black, 0.75);
    const glm::dvec2 centroid = (glm::dvec2(t[0]) + glm::dvec2(t[1]) + glm::dvec2(t[2])) / 3.0;
    diagram.label(centroid, names[i], LabelPlace::right);
  }
  legend_categories(diagram);
  diagram.legend_line("ideal edges", dc::black);
  diagram.legend_note("Triangles named by their colour in tinyrenderer's lesson.");
  diagram.legend_note(
      "Vermillion dots: outline pixels outside the fill (red, white, green: " + counts + ").");
  return SvgFigure{"03_tinyrenderer_fill_outline", diagram.svg()};
}

SvgFigure tinyrenderer_fill_outline_close_up() {
  // The green triangle, the one with the most outline pixels outside its fill.
  const Vertices& green = tri::ch02::tinyrenderer_triangles[2].vertices;
  const int size = tri::ch02::tinyrenderer_image_size;
  Canvas categories(size, size, dc::empty);
  const OutlineCount count = paint_fill_and_outline(categories, green);
  PixelDiagram diagram({118, 148}, {182, 182},
                       "tinyrenderer's green triangle zoomed: outline pixels outside the fill", 12);
  diagram.fill_from(categories, dc::empty);
  for (int y = 0; y < categories.height(); ++y) {
    for (int x = 0; x < categories.width(); ++x) {
      if (categories.pixel(x, y) == outline_outside) diagram.mark({x, y}, PixelMark::cross);
    }
  }
  diagram.triangle(green[0], green[1], green[2], dc::black, 1.25);
  diagram.vertex(green[0], "P0", LabelPlace::below_left);
  diagram.vertex(green[1], "P1", LabelPlace::below_right);
  diagram.vertex(green[2], "P2", LabelPlace::above_right);
  legend_categories(diagram);
  diagram.legend_mark("outline outside the fill", PixelMark::cross);
  diagram.legend_line("ideal edges", dc::black);
  diagram.legend_note(std::to_string(count.outside) + " of the outline's " +
                      std::to_string(count.outline) +
                      " pixels lie outside the fill, all on the two edges wider than tall.");
  return SvgFigure{"03_tinyrenderer_fill_outline_close_up", diagram.svg()};
}

SvgFigure trap_one_short() {
  const auto [a, b, c] = hand_triangle;
  Canvas drawn(16, 16);
  drawn.enable_write_counts();
  draw_filled_triangle(drawn, a, b, c, dc::black);
  PixelDiagram diagram =
      hand_diagram("Loops that stop one short lose the top row and each span's end");
  const SortedTriangle t = sort_by_y(a, b, c);
  for (int y = 0; y < drawn.height(); ++y) {
    int right_end = -1;
    for (int x = 0; x < drawn.width(); ++x) {
      if (drawn.write_count(x, y) == 0) continue;
      diagram.fill({x, y}, dc::covered);
      right_end = x;
    }
    if (right_end < 0) continue;
    diagram.mark({right_end, y}, PixelMark::cross, dc::vermillion);
    if (y == t.p2.y) {
      for (int x = 0; x <= right_end; ++x) {
        if (drawn.write_count(x, y) > 0) diagram.mark({x, y}, PixelMark::square, dc::vermillion);
      }
    }
  }
  diagram.legend_fill("our fill", dc::covered);
  diagram.legend_mark("lost to x < x_right (the span's last column)", PixelMark::cross,
                      dc::vermillion);
  diagram.legend_mark("lost to y < P2.y (the top row)", PixelMark::square, dc::vermillion);
  diagram.legend_line("ideal triangle edges", dc::dark_gray);
  return SvgFigure{"03_trap_one_short", diagram.svg()};
}

SvgFigure trap_no_pop_back() {
  const auto [a, b, c] = hand_triangle;
  const SortedTriangle t = sort_by_y(a, b, c);
  const EdgeXs e = interpolate_edges(t, triangle_rows(t));
  std::vector<double> kept = e.x01;  // the port: pop_back commented out
  kept.insert(kept.end(), e.x12.begin(), e.x12.end());
  const LeftRightXs wrong_ends = choose_left_right(e.x02, kept);
  Canvas right(16, 16), wrong(16, 16);
  right.enable_write_counts();
  wrong.enable_write_counts();
  draw_spans(right, t.p0.y, choose_left_right(e.x02, concatenate_short_sides(e.x01, e.x12)),
             dc::black);
  draw_spans(wrong, t.p0.y, wrong_ends, dc::black);
  PixelDiagram diagram =
      hand_diagram("Without pop_back, rows above P1 take their right end from the row below");
  int only_right = 0;
  for (int y = 0; y < right.height(); ++y) {
    for (int x = 0; x < right.width(); ++x) {
      const bool in_right = right.write_count(x, y) > 0, in_wrong = wrong.write_count(x, y) > 0;
      if (in_right) diagram.fill({x, y}, dc::covered);
      if (in_right && !in_wrong) ++only_right;
      if (in_wrong && !in_right) {
        diagram.fill({x, y}, dc::orange);
        diagram.mark({x, y}, PixelMark::cross);
      }
    }
  }
  for (std::size_t i = 0; i < wrong_ends.x_right.size(); ++i) {
    const glm::dvec2 p(wrong_ends.x_right[i], t.p0.y + static_cast<int>(i));
    diagram.point(p, dc::vermillion, 4);
    diagram.label(p, short_number(p.x), LabelPlace::right, dc::vermillion);
  }
  diagram.legend_fill("drawn either way", dc::covered);
  diagram.legend_fill("drawn only with P1 twice", dc::orange);
  diagram.legend_mark("the extra pixels", PixelMark::cross);
  diagram.legend_line("ideal triangle edges", dc::dark_gray);
  diagram.legend_note("Vermillion dots: x_right with P1 twice; its 7th value (row 6) is never");
  diagram.legend_note("drawn, as x02 has 6 rows. Pixels drawn only without the copy: " +
                      std::to_string(only_right) + ".");
  return SvgFigure{"03_trap_no_pop_back", diagram.svg()};
}

}  // namespace tri::ch03::figures
