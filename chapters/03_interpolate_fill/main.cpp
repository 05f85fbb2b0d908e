// Chapter 03's figures: each step of Gambetta's DrawFilledTriangle on one small triangle, his
// Figure 7-3 (the fill with the outline on top), and the traps of the C++ port.
#include <array>
#include <utility>
#include <vector>

#include "centered_view.hpp"
#include "figures.hpp"
#include "fill_steps.hpp"
#include "filled_triangle.hpp"
#include "wireframe.hpp"

namespace {

using tri::Canvas;
using tri::Color;
using namespace tri::ch03;

constexpr Color background{40, 40, 40, 255};
constexpr Color outline_gray{110, 110, 110, 255};
constexpr Color dim_yellow{90, 90, 30, 255};
constexpr int zoom = 16;

// The small triangle the step figures share: P0 at the bottom, P1 to the right, P2 on top.
constexpr glm::ivec2 demo_p0{3, 1}, demo_p1{21, 9}, demo_p2{8, 19};
Canvas demo_canvas() {
  return Canvas(25, 21, background);
}

int round_to_column(double x) {
  return nearest_column(x, 1 << 20);
}

// Puts one pixel per array entry, at (nearest column of xs[i], first_row + i).
void plot_xs(Canvas& canvas, int first_row, const std::vector<double>& xs, Color color) {
  for (std::size_t i = 0; i < xs.size(); ++i) {
    canvas.put_pixel(round_to_column(xs[i]), first_row + static_cast<int>(i), color);
  }
}

// Every pixel written on `drawn` (a counting canvas), painted in `color` on `canvas`.
void paint_written(Canvas& canvas, const Canvas& drawn, Color color) {
  for (int y = 0; y < canvas.height(); ++y) {
    for (int x = 0; x < canvas.width(); ++x) {
      if (drawn.write_count(x, y) > 0) canvas.put_pixel(x, y, color);
    }
  }
}

// Two canvases of equal height next to each other, one grey column between them.
Canvas side_by_side(const Canvas& left, const Canvas& right) {
  Canvas both(left.width() + 1 + right.width(), left.height(), tri::colors::gray);
  for (int y = 0; y < left.height(); ++y) {
    for (int x = 0; x < left.width(); ++x) both.put_pixel(x, y, left.pixel(x, y));
    for (int x = 0; x < right.width(); ++x) {
      both.put_pixel(left.width() + 1 + x, y, right.pixel(x, y));
    }
  }
  return both;
}

// The w x h pixels of `canvas` whose bottom-left corner is (x0, y0).
Canvas crop(const Canvas& canvas, int x0, int y0, int w, int h) {
  Canvas part(w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) part.put_pixel(x, y, canvas.pixel(x0 + x, y0 + y));
  }
  return part;
}

// Step 1: the outline in grey, P0 red, P1 green, P2 blue, whatever order they came in.
Canvas step1_sorted() {
  Canvas canvas = demo_canvas();
  tri::ch02::draw_wireframe_triangle(canvas, demo_p2, demo_p0, demo_p1, outline_gray);
  const SortedTriangle t = sort_by_y(demo_p2, demo_p0, demo_p1);
  canvas.put_pixel(t.p0, tri::colors::red);
  canvas.put_pixel(t.p1, tri::colors::green);
  canvas.put_pixel(t.p2, tri::colors::blue);
  return canvas;
}

// Step 2: one pixel per row for x02 (blue), x01 (red) and x12 (green); row y1 holds P1 twice,
// once from x01 and once from x12 (yellow).
Canvas step2_edges() {
  Canvas canvas = demo_canvas();
  const SortedTriangle t = sort_by_y(demo_p0, demo_p1, demo_p2);
  const EdgeXs e = interpolate_edges(t, triangle_rows(t));
  plot_xs(canvas, t.p0.y, e.x02, tri::colors::blue);
  plot_xs(canvas, t.p0.y, e.x01, tri::colors::red);
  plot_xs(canvas, t.p1.y, e.x12, tri::colors::green);
  canvas.put_pixel(t.p1, tri::colors::yellow);
  return canvas;
}

// Step 3: x012 (white) beside x02 (blue). Right: x01 + x12 without dropping P1's copy; from row
// y1 up every value sits one row too high (red where it differs).
Canvas step3_concatenate() {
  const SortedTriangle t = sort_by_y(demo_p0, demo_p1, demo_p2);
  const EdgeXs e = interpolate_edges(t, triangle_rows(t));
  const auto x012 = concatenate_short_sides(e.x01, e.x12);
  std::vector<double> doubled = e.x01;
  doubled.insert(doubled.end(), e.x12.begin(), e.x12.end());
  Canvas right = demo_canvas(), wrong = demo_canvas();
  for (Canvas* canvas : {&right, &wrong}) plot_xs(*canvas, t.p0.y, e.x02, tri::colors::blue);
  plot_xs(right, t.p0.y, x012, tri::colors::white);
  for (std::size_t i = 0; i < doubled.size(); ++i) {
    const bool moved = i >= x012.size() || round_to_column(doubled[i]) != round_to_column(x012[i]);
    wrong.put_pixel(round_to_column(doubled[i]), t.p0.y + static_cast<int>(i),
                    moved ? tri::colors::red : tri::colors::white);
  }
  return side_by_side(right, wrong);
}

// Step 4: the middle row (dim yellow band) decides; x_left cyan, x_right magenta.
Canvas step4_left_right() {
  Canvas canvas = demo_canvas();
  const SortedTriangle t = sort_by_y(demo_p0, demo_p1, demo_p2);
  EdgeXs e = interpolate_edges(t, triangle_rows(t));
  auto x012 = concatenate_short_sides(std::move(e.x01), e.x12);
  const std::size_t middle = middle_row_index(e.x02.size());
  canvas.fill_span(t.p0.y + static_cast<int>(middle), 0, canvas.width(), dim_yellow);
  const SpanEnds spans = choose_left_right(std::move(e.x02), std::move(x012));
  plot_xs(canvas, t.p0.y, spans.x_left, tri::colors::cyan);
  plot_xs(canvas, t.p0.y, spans.x_right, tri::colors::magenta);
  return canvas;
}

// Step 5: every row's span, in two alternating shades so the segments show (Gambetta's 7-2).
Canvas step5_spans() {
  Canvas canvas = demo_canvas();
  const SortedTriangle t = sort_by_y(demo_p0, demo_p1, demo_p2);
  EdgeXs e = interpolate_edges(t, triangle_rows(t));
  auto x012 = concatenate_short_sides(std::move(e.x01), e.x12);
  const SpanEnds spans = choose_left_right(std::move(e.x02), std::move(x012));
  for (std::size_t i = 0; i < spans.x_left.size(); ++i) {
    const Color shade = i % 2 == 0 ? Color{60, 200, 90, 255} : Color{30, 130, 60, 255};
    draw_spans(canvas, t.p0.y + static_cast<int>(i), {{spans.x_left[i]}, {spans.x_right[i]}},
               shade);
  }
  return canvas;
}

// Figure 7-3: green fill, black outline on top, outline pixels outside the fill in red.
Canvas fill_with_outline(Canvas canvas, std::array<glm::ivec2, 3> v, Color fill_color,
                         Color outline_color) {
  Canvas fill(canvas.width(), canvas.height());
  fill.enable_write_counts();
  draw_filled_triangle(fill, v[0], v[1], v[2], fill_color);
  Canvas outline(canvas.width(), canvas.height());
  outline.enable_write_counts();
  tri::ch02::draw_wireframe_triangle(outline, v[0], v[1], v[2], outline_color);
  paint_written(canvas, fill, fill_color);
  paint_written(canvas, outline, outline_color);
  for (int y = 0; y < canvas.height(); ++y) {
    for (int x = 0; x < canvas.width(); ++x) {
      if (outline.write_count(x, y) > 0 && fill.write_count(x, y) == 0) {
        canvas.put_pixel(x, y, tri::colors::red);
      }
    }
  }
  return canvas;
}

std::array<glm::ivec2, 3> figure_7_3_vertices(Canvas& canvas, int flip) {
  tri::CenteredView view(canvas);
  return {view.to_canvas({-200, -250 * flip}), view.to_canvas({200, 50 * flip}),
          view.to_canvas({20, 250 * flip})};
}

Canvas figure_7_3(int flip) {
  Canvas canvas(600, 600, tri::colors::white);
  return fill_with_outline(canvas, figure_7_3_vertices(canvas, flip), tri::colors::green,
                           tri::colors::black);
}

// The same stretch of the wide edge P0-P1 in both, magnified: upright left, flipped right.
Canvas figure_7_3_close_up() {
  const Canvas upright = figure_7_3(1), flipped = figure_7_3(-1);
  // The edge runs from (100,50) to (500,350) upright and from (100,550) to (500,250) flipped.
  return tri::magnified(
      side_by_side(crop(upright, 280, 180, 40, 40), crop(flipped, 280, 380, 40, 40)), 10);
}

// tinyrenderer's three triangles, filled in their colours with a grey outline on top.
Canvas tinyrenderer_fill_with_outline() {
  Canvas canvas(200, 200);
  const std::array<std::array<glm::ivec2, 3>, 3> triangles{{
      {{{10, 70}, {50, 160}, {70, 80}}},
      {{{180, 50}, {150, 1}, {70, 180}}},
      {{{180, 150}, {120, 160}, {130, 180}}},
  }};
  const std::array<Color, 3> colors{Color{200, 0, 0, 255}, Color{200, 200, 200, 255},
                                    Color{0, 170, 0, 255}};
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    canvas = fill_with_outline(std::move(canvas), triangles[i], colors[i], tri::colors::blue);
  }
  return canvas;
}

// Loops that stop one short: white is drawn either way, red is what `y < P2.y` (the top row)
// and `x < x_right` (each span's right end) would lose.
Canvas trap_one_short() {
  Canvas counted = demo_canvas();
  counted.enable_write_counts();
  draw_filled_triangle(counted, demo_p0, demo_p1, demo_p2, tri::colors::white);
  Canvas canvas = demo_canvas();
  for (int y = 0; y < canvas.height(); ++y) {
    int right_end = -1;
    for (int x = 0; x < canvas.width(); ++x) {
      if (counted.write_count(x, y) == 0) continue;
      canvas.put_pixel(x, y, tri::colors::white);
      right_end = x;
    }
    if (right_end >= 0) canvas.put_pixel(right_end, y, tri::colors::red);
    if (y == demo_p2.y) canvas.put_pixel(demo_p2, tri::colors::red);
  }
  return canvas;
}

// The pop_back left out: white is the same, red is drawn only with P1 twice, blue only without.
Canvas trap_no_pop_back() {
  const SortedTriangle t = sort_by_y(demo_p0, demo_p1, demo_p2);
  const EdgeXs e = interpolate_edges(t, triangle_rows(t));
  std::vector<double> doubled = e.x01;
  doubled.insert(doubled.end(), e.x12.begin(), e.x12.end());
  Canvas right = demo_canvas(), wrong = demo_canvas();
  right.enable_write_counts();
  wrong.enable_write_counts();
  draw_spans(right, t.p0.y, choose_left_right(e.x02, concatenate_short_sides(e.x01, e.x12)),
             tri::colors::white);
  draw_spans(wrong, t.p0.y, choose_left_right(e.x02, doubled), tri::colors::white);
  Canvas canvas = demo_canvas();
  for (int y = 0; y < canvas.height(); ++y) {
    for (int x = 0; x < canvas.width(); ++x) {
      const bool in_right = right.write_count(x, y) > 0, in_wrong = wrong.write_count(x, y) > 0;
      if (in_right && in_wrong) canvas.put_pixel(x, y, tri::colors::white);
      if (in_wrong && !in_right) canvas.put_pixel(x, y, tri::colors::red);
      if (in_right && !in_wrong) canvas.put_pixel(x, y, tri::colors::blue);
    }
  }
  return canvas;
}

}  // namespace

int main(int argc, char** argv) {
  return tri::run_chapter_program(
      argc, argv, "03_interpolate_fill",
      "Chapter 03, Gambetta's filled triangle: one figure per step on a small triangle\n"
      "(03_step1_sorted.png ... 03_step5_spans.png, magnified 16x), Figure 7-3 with the outline\n"
      "on top of the fill, upright and flipped (03_figure_7_3.png, 03_figure_7_3_flipped.png,\n"
      "03_figure_7_3_close_up.png), tinyrenderer's triangles filled and outlined\n"
      "(03_tinyrenderer_fill_outline.png) and the port's traps (03_trap_one_short.png,\n"
      "03_trap_no_pop_back.png).",
      [](tri::FigureWriter& figures) {
        figures.save_png("03_step1_sorted", tri::magnified(step1_sorted(), zoom));
        figures.save_png("03_step2_edges", tri::magnified(step2_edges(), zoom));
        figures.save_png("03_step3_concatenate", tri::magnified(step3_concatenate(), zoom));
        figures.save_png("03_step4_left_right", tri::magnified(step4_left_right(), zoom));
        figures.save_png("03_step5_spans", tri::magnified(step5_spans(), zoom));
        figures.save_png("03_figure_7_3", figure_7_3(1));
        figures.save_png("03_figure_7_3_flipped", figure_7_3(-1));
        figures.save_png("03_figure_7_3_close_up", figure_7_3_close_up());
        figures.save_png("03_tinyrenderer_fill_outline",
                         tri::magnified(tinyrenderer_fill_with_outline(), 4));
        figures.save_png("03_trap_one_short", tri::magnified(trap_one_short(), zoom));
        figures.save_png("03_trap_no_pop_back", tri::magnified(trap_no_pop_back(), zoom));
      });
}
