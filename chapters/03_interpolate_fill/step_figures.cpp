#include "chapters/03_interpolate_fill/step_figures.hpp"

#include <array>
#include <cstddef>
#include <utility>
#include <vector>

#include "chapters/03_interpolate_fill/diagram_support.hpp"
#include "chapters/03_interpolate_fill/fill_steps.hpp"

namespace tri::ch03::figures {
namespace {

namespace dc = diagram_colors;

constexpr Color light_yellow{250, 242, 170, 255};
constexpr Color pale_blue{180, 218, 240, 255};
// Orange text is too light on white; labels of orange dots use this darker tone.
constexpr Color orange_text{160, 100, 0, 255};

// The hand triangle after step 1.
SortedTriangle sorted_hand() {
  return sort_by_y(hand_triangle[0], hand_triangle[1], hand_triangle[2]);
}

// One dot per array entry at (x, first_row + i), each labelled with its value on one side.
void plot_values(PixelDiagram& diagram, int first_row, const std::vector<double>& xs, Color color,
                 LabelPlace place, std::size_t skip_label = static_cast<std::size_t>(-1)) {
  for (std::size_t i = 0; i < xs.size(); ++i) {
    const glm::dvec2 p(xs[i], first_row + static_cast<int>(i));
    diagram.point(p, color, 5);
    if (i != skip_label) {
      diagram.label(p, short_number(xs[i]), place, color == dc::orange ? orange_text : color);
    }
  }
}

std::string joined(const std::vector<double>& xs) {
  std::string out;
  for (const double x : xs) out += (out.empty() ? "" : ", ") + short_number(x);
  return out;
}

}  // namespace

SvgFigure step1_sorted() {
  const auto [a, b, c] = hand_triangle;
  // Passed as P2, P0, P1 on purpose, so that sorting has something to do.
  const std::array<glm::ivec2, 3> passed{c, a, b};
  PixelDiagram before({-1, -1}, {8, 6}, "As passed: (2, 5), (1, 0), (6, 3)", 48);
  before.triangle(a, b, c, dc::dark_gray, 1.5);
  const std::array<const char*, 3> names{"1st", "2nd", "3rd"};
  const std::array<LabelPlace, 3> places{LabelPlace::above_right, LabelPlace::below_right,
                                         LabelPlace::below_right};
  for (std::size_t i = 0; i < passed.size(); ++i) before.vertex(passed[i], names[i], places[i]);
  before.legend_line("ideal triangle edges", dc::dark_gray);

  const SortedTriangle t = sort_by_y(passed[0], passed[1], passed[2]);
  PixelDiagram after = hand_diagram("After sort_by_y: y0 <= y1 <= y2");
  const std::array<std::pair<int, const char*>, 3> rows{
      {{t.p0.y, "y0 = 0"}, {t.p1.y, "y1 = 3"}, {t.p2.y, "y2 = 5"}}};
  for (const auto& [y, name] : rows) {
    after.line({-1.5, y}, {8.5, y}, dc::blue, 1.5, true);
    after.label({-1.5, y}, name, LabelPlace::above_right, dc::blue);
  }
  after.legend_line("ideal triangle edges", dc::dark_gray);
  after.legend_line("the row of each sorted vertex", dc::blue, true);
  after.legend_note("The fill covers exactly rows y0 to y2; P1 splits them into two short sides.");
  const std::array<PixelDiagram, 2> panels{before, after};
  return SvgFigure{
      "03_step1_sorted",
      side_by_side(panels, "Step 1: the vertices renamed bottom to top, P0 lowest, P2 highest")};
}

SvgFigure step2_edges() {
  const SortedTriangle t = sorted_hand();
  const EdgeXs e = interpolate_edges(t, triangle_rows(t));
  PixelDiagram diagram = hand_diagram(
      "Step 2: interpolate gives each edge one x per row, both end rows included", false);
  diagram.line(t.p0, t.p2, dc::blue);
  diagram.line(t.p0, t.p1, dc::vermillion);
  diagram.line(t.p1, t.p2, dc::bluish_green);
  plot_values(diagram, t.p0.y, e.x02, dc::blue, LabelPlace::left);
  plot_values(diagram, t.p0.y, e.x01, dc::vermillion, LabelPlace::right, e.x01.size() - 1);
  // x12[0] sits on x01[3] (P1): a smaller dot on top shows both, one label says so.
  for (std::size_t i = 0; i < e.x12.size(); ++i) {
    const glm::dvec2 p(e.x12[i], t.p1.y + static_cast<int>(i));
    diagram.point(p, dc::bluish_green, i == 0 ? 3 : 5);
    if (i > 0) diagram.label(p, short_number(e.x12[i]), LabelPlace::right, dc::bluish_green);
  }
  diagram.label(t.p1, "x01[3] = x12[0] = 6", LabelPlace::above_left);
  diagram.legend_line("x02: tall side P0-P2, rows 0-5", dc::blue);
  diagram.legend_line("x01: P0-P1, rows 0-3", dc::vermillion);
  diagram.legend_line("x12: P1-P2, rows 3-5", dc::bluish_green);
  diagram.legend_note("Dots: the exact x on each row, labelled. Row y1 = 3 is in x01 and in x12:");
  diagram.legend_note("P1's x is computed twice (the small green dot on the vermillion one).");
  diagram.legend_note("x02 = " + joined(e.x02) + " · x01 = " + joined(e.x01) +
                      " · x12 = " + joined(e.x12));
  return SvgFigure{"03_step2_edges", diagram.svg()};
}

SvgFigure step3_concatenate() {
  const SortedTriangle t = sorted_hand();
  const EdgeXs e = interpolate_edges(t, triangle_rows(t));
  const std::vector<double> x012 = concatenate_short_sides(e.x01, e.x12);
  std::vector<double> kept = e.x01;  // the port: pop_back commented out
  kept.insert(kept.end(), e.x12.begin(), e.x12.end());

  PixelDiagram right = hand_diagram("x01 without its last value, then x12");
  plot_values(right, t.p0.y, e.x02, dc::blue, LabelPlace::left);
  plot_values(right, t.p0.y, x012, dc::orange, LabelPlace::right);
  right.legend_line("ideal triangle edges", dc::dark_gray);
  right.legend_note("blue dots: x02 = " + joined(e.x02));
  right.legend_note("orange dots: x012 = " + joined(x012));
  right.legend_note("6 values for 6 rows: each dot on its edge");

  PixelDiagram wrong = hand_diagram("P1's copy kept: x01 + x12");
  plot_values(wrong, t.p0.y, e.x02, dc::blue, LabelPlace::left);
  plot_values(wrong, t.p0.y, kept, dc::orange, LabelPlace::right);
  for (std::size_t i = x012.size() - 2; i < kept.size(); ++i) {
    wrong.mark({nearest_column(kept[i], 1 << 20), t.p0.y + static_cast<int>(i)}, PixelMark::cross,
               dc::vermillion);
  }
  wrong.legend_line("ideal triangle edges", dc::dark_gray);
  wrong.legend_mark("a value one row too high, off its edge", PixelMark::cross, dc::vermillion);
  wrong.legend_note("orange dots: x01 + x12 = " + joined(kept));
  wrong.legend_note("7 values for 6 rows: the last lands on row 6,");
  wrong.legend_note("one row above the triangle");
  const std::array<PixelDiagram, 2> panels{right, wrong};
  return SvgFigure{
      "03_step3_concatenate",
      side_by_side(panels,
                   "Step 3: x012 must drop x01's copy of P1, or the upper side moves up a row")};
}

SvgFigure step4_left_right() {
  const SortedTriangle t = sorted_hand();
  EdgeXs e = interpolate_edges(t, triangle_rows(t));
  const std::vector<double> x012 = concatenate_short_sides(e.x01, e.x12);
  const std::size_t middle = middle_row_index(e.x02.size());
  const int middle_row = t.p0.y + static_cast<int>(middle);
  const std::string comparison = "x02[" + std::to_string(middle) +
                                 "] = " + short_number(e.x02[middle]) + " < x012[" +
                                 std::to_string(middle) + "] = " + short_number(x012[middle]);
  const LeftRightXs ends = choose_left_right(e.x02, x012);

  PixelDiagram diagram =
      hand_diagram("Step 4: compared on the middle row, x02 is the left side, x012 the right");
  for (int x = -1; x <= 8; ++x) diagram.fill({x, middle_row}, light_yellow);
  for (std::size_t i = 0; i < ends.x_left.size(); ++i) {
    const int y = t.p0.y + static_cast<int>(i);
    const int left = nearest_column(ends.x_left[i], 1 << 20);
    const int right = nearest_column(ends.x_right[i], 1 << 20);
    diagram.fill({left, y}, left == right ? dc::purple : dc::sky_blue);
    if (right != left) diagram.fill({right, y}, dc::orange);
  }
  plot_values(diagram, t.p0.y, ends.x_left, dc::blue, LabelPlace::left);
  plot_values(diagram, t.p0.y, ends.x_right, dc::vermillion, LabelPlace::right);
  diagram.legend_fill("middle row m = floor(6 / 2) = 3", light_yellow);
  diagram.legend_fill("column of x_left", dc::sky_blue);
  diagram.legend_fill("column of x_right", dc::orange);
  diagram.legend_fill("both", dc::purple);
  diagram.legend_line("ideal triangle edges", dc::dark_gray);
  diagram.legend_note("Blue dots: x_left = x02; vermillion dots: x_right = x012, as labelled.");
  diagram.legend_note("On row " + std::to_string(middle_row) + ", " + comparison +
                      ", so x02 is the left side.");
  diagram.legend_note("Columns: nearest, halves up (step 5).");
  return SvgFigure{"03_step4_left_right", diagram.svg()};
}

SvgFigure step5_spans() {
  const SortedTriangle t = sorted_hand();
  EdgeXs e = interpolate_edges(t, triangle_rows(t));
  const LeftRightXs ends = choose_left_right(e.x02, concatenate_short_sides(e.x01, e.x12));
  PixelDiagram diagram =
      hand_diagram("Step 5: each row from the column of x_left to that of x_right");
  for (std::size_t i = 0; i < ends.x_left.size(); ++i) {
    const int y = t.p0.y + static_cast<int>(i);
    const int left = nearest_column(ends.x_left[i], 1 << 20);
    const int right = nearest_column(ends.x_right[i], 1 << 20);
    for (int x = left; x <= right; ++x) {
      diagram.fill({x, y}, i % 2 == 0 ? dc::sky_blue : pale_blue);
      if (!centre_in_triangle(t.p0, t.p1, t.p2, {x, y})) {
        diagram.mark({x, y}, PixelMark::cross, dc::vermillion);
      }
    }
    diagram.point({ends.x_left[i], y}, dc::black, 3.5);
    diagram.point({ends.x_right[i], y}, dc::black, 3.5);
    diagram.label({7, y}, std::to_string(left) + ".." + std::to_string(right), LabelPlace::right);
  }
  diagram.legend_fill("span, even rows", dc::sky_blue);
  diagram.legend_fill("span, odd rows", pale_blue);
  diagram.legend_mark("centre outside the triangle", PixelMark::cross, dc::vermillion);
  diagram.legend_line("ideal triangle edges", dc::dark_gray);
  diagram.legend_note("Black dots: exact x_left and x_right; right: each row's columns.");
  diagram.legend_note("Rounded ends reach up to half a pixel past the edge (crosses).");
  return SvgFigure{"03_step5_spans", diagram.svg()};
}

}  // namespace tri::ch03::figures
