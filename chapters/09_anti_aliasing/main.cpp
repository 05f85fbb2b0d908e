// Chapter 09's figures: how much of each pixel a triangle covers, exactly, as diagrams.
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "chapters/07_exact_coverage/coverage_oracle.hpp"
#include "chapters/07_exact_coverage/jittered_mesh.hpp"
#include "chapters/09_anti_aliasing/area_cells.hpp"
#include "chapters/09_anti_aliasing/area_oracle.hpp"
#include "chapters/09_anti_aliasing/sampling.hpp"
#include "common/figures.hpp"
#include "common/pixel_diagram.hpp"

namespace {

namespace dc = tri::diagram_colors;
using tri::LabelPlace;

// White for an empty pixel to sky blue for a full one, in proportion to the coverage.
tri::Color shade(double coverage) {
  const auto channel = [&](int full) {
    return static_cast<std::uint8_t>(255 + (full - 255) * coverage + 0.5);
  };
  return {channel(dc::sky_blue.r), channel(dc::sky_blue.g), channel(dc::sky_blue.b), 255};
}

// The covered percent, rounded down, so only a whole pixel reads 100 and a sliver reads "<1".
std::string percent(const tri::ch09::Fraction& coverage) {
  const auto whole = static_cast<int>(coverage.numerator() * 100 / coverage.denominator());
  return whole == 0 ? "<1" : std::to_string(whole);
}

tri::SvgFigure exact_coverage_figure() {
  const tri::Triangle t = {{{1.25, 0.75}, {10.5, 2.375}, {4.0, 7.25}}};
  tri::PixelDiagram d({0, 0}, {12, 8},
                      "Exact coverage: the part of each pixel square inside the triangle", 40);
  d.show_centres(false);  // the squares matter here, not their centres
  for (const auto& p : tri::ch09::exact_coverages(t)) {
    d.fill(p.pixel, shade(p.coverage.to_double()));
    d.pixel_text(p.pixel, percent(p.coverage));
  }
  d.triangle(t[0], t[1], t[2], dc::vermillion);
  d.vertex(t[0], "A", LabelPlace::below_left);
  d.vertex(t[1], "B", LabelPlace::right);
  d.vertex(t[2], "C", LabelPlace::above_right);
  d.legend_fill("pixel wholly inside (100)", shade(1));
  d.legend_fill("pixel partly inside: shade and number = percent covered", shade(0.4));
  d.legend_line("the triangle", dc::vermillion);
  const tri::ch09::Fraction area = tri::ch09::exact_area(t);
  d.legend_note("Numbers: percent of the pixel covered, rounded down. All the coverages add up");
  d.legend_note("to the triangle's area, " + area.text() + " = " +
                std::to_string(area.to_double()).substr(0, 8) + " pixels, exactly.");
  return {"09_exact_coverage", d.svg()};
}

// Which side of the pixel a figure measures each edge piece from.
enum class MeasuredFrom { left_side, right_side };

// A fraction as a learner writes it: "0", "-1", "5/12", with a sign when asked.
std::string exact_text(const tri::ch09::Fraction& f, bool sign = false) {
  const std::string text =
      f.denominator() == 1 ? std::to_string(static_cast<long long>(f.numerator())) : f.text();
  return sign && !(f < tri::ch09::Fraction(0)) ? "+" + text : text;
}

// One pixel and the edges in its row, each piece with what it adds: step 1 measures h from the
// pixel's left side (a piece right of the pixel counts its whole width), step 4 from the right
// side (a piece left of the pixel counts its whole width: the cover). The legend lists every
// piece, so the sum can be done by hand.
tri::SvgFigure edge_pieces_figure(MeasuredFrom from) {
  // Counter-clockwise (y up): the left edge CA passes left of pixel (1, 0), the right edge BC
  // rises through it above y = 0 and right of it below.
  const tri::Triangle t = {{{-0.5, -1.5}, {2.5, -1.5}, {0.5, 1.5}}};
  const glm::ivec2 pixel{1, 0};
  const bool left = from == MeasuredFrom::left_side;
  tri::PixelDiagram d(
      {-2, -2}, {4, 2},
      left ? "Step 1: what each edge piece adds to pixel (1, 0), h from its left side"
           : "Step 4: cover and area of each edge piece in cell (1, 0), to its right side",
      72);
  using tri::ch09::Fraction;
  const Fraction coverage = tri::ch09::exact_coverage(t, pixel);
  d.fill(pixel, shade(coverage.to_double()));
  d.frame(pixel, pixel, dc::black, 3);
  const double x0 = pixel.x - 0.5, x1 = pixel.x + 0.5, y0 = pixel.y - 0.5, y1 = pixel.y + 0.5;
  const std::array<tri::Color, 3> colors = {dc::blue, dc::bluish_green, dc::purple};
  const std::array<std::string, 3> names = {"AB", "BC", "CA"};
  Fraction sum = 0;
  std::string sum_text;
  for (std::size_t k = 0; k < 3; ++k) {
    const glm::dvec2 a = t[k], b = t[(k + 1) % 3];
    const tri::ch09::EdgeInPixelRow parts = tri::ch09::edge_in_pixel_row(a, b, pixel);
    struct Part {
      Fraction height, width;  // what it adds is height x width
      glm::dvec2 low, high;    // where it lies
      std::string where, width_name;
      LabelPlace place;
    };
    const Fraction mean = left ? parts.inside_mean_x : Fraction(1) - parts.inside_mean_x;
    const std::array<Part, 3> pieces = {{
        {parts.left_height,
         left ? 0 : 1,
         {-1e9, y0},
         {x0, y1},
         "left of the pixel",
         left ? "h" : "whole width",
         LabelPlace::left},
        {parts.inside_height,
         mean,
         {x0, y0},
         {x1, y1},
         "inside",
         left ? "mean h" : "mean distance to the right side",
         LabelPlace::right},
        {parts.right_height,
         left ? 1 : 0,
         {x1, y0},
         {1e9, y1},
         "right of the pixel",
         left ? "whole width" : "distance",
         LabelPlace::right},
    }};
    for (const Part& part : pieces) {
      if (part.height == Fraction(0)) continue;
      const auto piece = tri::clip_segment(a, b, part.low, part.high);
      if (!piece || (*piece)[0] == (*piece)[1]) continue;  // a corner touched: no piece to draw
      const Fraction adds = part.height * part.width;
      const glm::dvec2 middle = ((*piece)[0] + (*piece)[1]) / 2.0;
      if (part.where == "inside") {  // the trapezoid between the piece and the measured side
        const double side = left ? x0 : x1;
        for (const glm::dvec2 end : *piece) d.line(end, {side, end.y}, colors[k], 2.5, true);
        d.line({side, (*piece)[0].y}, {side, (*piece)[1].y}, colors[k], 4);
      }
      d.label(middle + glm::dvec2(part.place == LabelPlace::left ? -0.1 : 0.1, 0),
              names[k] + ": " + exact_text(adds), part.place, colors[k]);
      d.legend_line(names[k] + " " + part.where + ": height " + exact_text(part.height, true) +
                        " x " + part.width_name + " " + exact_text(part.width) + " = " +
                        exact_text(adds),
                    colors[k]);
      sum = sum + adds;
      sum_text += (sum_text.empty() ? "" : " + ") + exact_text(adds);
    }
  }
  d.triangle(t[0], t[1], t[2], dc::vermillion);
  d.vertex(t[0], "A", LabelPlace::below_right);
  d.vertex(t[1], "B", LabelPlace::below_left);
  d.vertex(t[2], "C", LabelPlace::above_right);
  d.legend_fill("pixel (1, 0), shaded by its coverage " + exact_text(coverage),
                shade(coverage.to_double()));
  d.legend_line("the triangle ABC, counter-clockwise (y up); AB lies below the row and adds 0",
                dc::vermillion);
  if (left) {
    d.legend_note("h = x - the pixel's left side, 0 to 1. Sum: " + sum_text + " = " +
                  exact_text(sum) + " = +coverage.");
  } else {
    d.legend_note("Sum of cover and area: " + sum_text + " = " + exact_text(sum) +
                  "; coverage = -(cover + area) = " + exact_text(Fraction(0) - sum) + ".");
  }
  return {left ? "09_step1_edge_parts" : "09_step4_pixel_pieces", d.svg()};
}

tri::SvgFigure step1_edge_parts_figure() {
  return edge_pieces_figure(MeasuredFrom::left_side);
}

tri::SvgFigure step4_pixel_pieces_figure() {
  return edge_pieces_figure(MeasuredFrom::right_side);
}

// One panel: the pattern's samples in every pixel, blue inside the triangle and grey outside,
// each pixel shaded by the fraction of its samples inside.
tri::PixelDiagram samples_panel(const tri::Triangle& t, const tri::ch09::SamplePattern& pattern,
                                const std::string& title) {
  tri::PixelDiagram d({0, 0}, {7, 2}, title, 48);
  d.show_centres(false);
  const tri::Triangle scaled = {{t[0] * 32.0, t[1] * 32.0, t[2] * 32.0}};
  double error_sum = 0;
  int touched = 0;
  for (int y = 0; y <= 2; ++y) {
    for (int x = 0; x <= 7; ++x) {
      const double sampled = tri::ch09::sampled_coverage(t, {x, y}, pattern);
      const double exact = tri::ch09::exact_coverage(t, {x, y}).to_double();
      d.fill({x, y}, shade(sampled));
      for (const glm::ivec2 offset : pattern.offsets) {
        const glm::ivec2 sample = glm::ivec2{x, y} * 32 + offset;
        const bool inside = tri::ch07::oracle_covers(scaled, sample);
        d.point(glm::dvec2(sample) / 32.0, inside ? dc::blue : dc::dark_gray, inside ? 3 : 2);
      }
      if (exact > 0 && exact < 1) {
        d.pixel_text({x, y}, std::to_string(static_cast<int>(std::lround(sampled * 16))) + "/16",
                     dc::black);
      }
      if (sampled > 0 || exact > 0) {
        error_sum += std::abs(sampled - exact);
        ++touched;
      }
    }
  }
  d.triangle(t[0], t[1], t[2], dc::vermillion);
  d.legend_point("a sample inside the triangle (counted)", dc::blue, 3);
  d.legend_point("a sample outside", dc::dark_gray, 2);
  d.legend_fill("shade = fraction of the pixel's samples inside", shade(0.5));
  d.legend_line("the triangle's edge", dc::vermillion);
  d.legend_note("Each pixel holds the pattern's " + std::to_string(pattern.offsets.size()) +
                " samples, placed alike in every pixel; each is decided");
  d.legend_note("by chapter 07's top-left rule. Numbers: samples inside, where the edge crosses.");
  char note[96];
  std::snprintf(note, sizeof note, "Mean |sampled - exact| over %d pixels: %.3f", touched,
                error_sum / touched);
  d.legend_note(note);
  return d;
}

tri::SvgFigure sample_patterns_figure() {
  // A nearly horizontal edge, 1.5 degrees off, with the other two edges far outside: a grid's
  // samples stand in 4 rows, so the edge row's coverage moves in steps of 4/16; the rotated
  // pattern's stand in 16 rows.
  const tri::Triangle t = {{{-4, 1.125}, {12, 1.54296875}, {-4, 30}}};
  const std::array<tri::PixelDiagram, 2> panels = {
      samples_panel(t, tri::ch09::regular_grid(4), "4 x 4 regular grid"),
      samples_panel(t, tri::ch09::standard_pattern(16), "Standard 16-sample pattern")};
  return {
      "09_sample_patterns",
      tri::side_by_side(panels, "Sixteen samples per pixel on an edge 1.5 degrees off horizontal")};
}

// Draws one pixel's samples, given as offsets from its centre in 1/units pixel, blue inside the
// triangle and hollow grey outside (each decided by chapter 07's oracle); returns how many are in.
int draw_pixel_samples(tri::PixelDiagram& d, const tri::Triangle& t, glm::ivec2 pixel,
                       const std::vector<glm::ivec2>& offsets, int units, double radius) {
  const tri::Triangle scaled = {{t[0] * double(units), t[1] * double(units), t[2] * double(units)}};
  int inside = 0;
  for (const glm::ivec2 offset : offsets) {
    const glm::ivec2 sample = pixel * units + offset;
    const bool in = tri::ch07::oracle_covers(scaled, sample);
    inside += in ? 1 : 0;
    const glm::dvec2 at = glm::dvec2(sample) / double(units);
    d.point(at, in ? dc::blue : dc::dark_gray, radius);
    if (!in) d.point(at, tri::colors::white, radius * 0.6);  // hollow: outside, not counted
  }
  return inside;
}

// Three decimals, for a coverage written beside its sampled estimate.
std::string decimal3(double v) {
  char text[16];
  std::snprintf(text, sizeof text, "%.3f", v);
  return text;
}

// Counter-clockwise (y up): its lower edge rises gently through pixels 0 to 2 of row 0 (chosen so
// that 4 x 4 samples miss the area in all three), its other edges stay outside those pixels.
tri::Triangle gentle_edge_triangle() {
  return {{{-1, -131 / 256.0}, {3.5, 49 / 256.0}, {-1, 6}}};
}

tri::SvgFigure step2_supersampling_figure() {
  const tri::Triangle t = gentle_edge_triangle();
  tri::PixelDiagram d({0, -1}, {2, 0}, "Step 2: 4 x 4 samples counted against the exact area", 150);
  d.show_centres(false);
  const tri::ch09::SamplePattern grid = tri::ch09::regular_grid(4);
  for (int x = 0; x <= 2; ++x) {
    const glm::ivec2 pixel{x, 0};
    const double exact = tri::ch09::exact_coverage(t, pixel).to_double();
    const int k = draw_pixel_samples(d, t, pixel, grid.offsets, tri::ch09::sample_units, 6);
    d.frame(pixel, pixel, dc::black, 2.5);
    d.label({x - 0.45, -0.75}, "samples " + std::to_string(k) + "/16 = " + decimal3(k / 16.0),
            LabelPlace::right);
    d.label({x - 0.45, -1.0}, "exact area " + decimal3(exact), LabelPlace::right);
    d.label({x - 0.45, -1.25}, "error " + decimal3(k / 16.0 - exact), LabelPlace::right);
  }
  d.triangle(t[0], t[1], t[2], dc::vermillion);
  d.legend_point("a sample inside the triangle: counted", dc::blue, 6);
  d.legend_mark("a sample outside (hollow): not counted", tri::PixelMark::ring, dc::dark_gray);
  d.legend_line("the triangle's edge", dc::vermillion);
  d.legend_note("Each pixel: 16 samples at (k + 1/2)/4 across it, decided by chapter 07's rule.");
  d.legend_note("Below it: the count k/16, step 1's exact area of the same pixel, and the error.");
  d.legend_note("The count moves in whole sixteenths; the area moves with the edge.");
  return {"09_step2_supersampling", d.svg()};
}

tri::SvgFigure step7_pixman_grid_figure() {
  // pixman's a8 sample grid (pixman-private.h, 8 bits): 15 rows at 2185 + 4369 j and 17 columns
  // at 1928 + 3855 i, in 1/65536 of a pixel from its low side; 15 x 17 = 255, the byte's range.
  constexpr int fixed_one = 65536;
  std::vector<glm::ivec2> offsets;
  for (int j = 0; j < 15; ++j) {
    for (int i = 0; i < 17; ++i) {
      offsets.push_back({1928 + 3855 * i - fixed_one / 2, 2185 + 4369 * j - fixed_one / 2});
    }
  }
  const tri::Triangle t = gentle_edge_triangle();
  const glm::ivec2 pixel{1, 0};  // the step 2 figure's middle pixel
  tri::PixelDiagram d(pixel, pixel, "Step 7: pixman's 15 x 17 samples in one pixel", 420);
  d.show_centres(false);
  const int count = draw_pixel_samples(d, t, pixel, offsets, fixed_one, 4);
  d.frame(pixel, pixel, dc::black, 2.5);
  d.triangle(t[0], t[1], t[2], dc::vermillion);
  const double exact = tri::ch09::exact_coverage(t, pixel).to_double();
  d.legend_point("a sample inside: counted", dc::blue, 4);
  d.legend_mark("a sample outside (hollow)", tri::PixelMark::ring, dc::dark_gray);
  d.legend_line("the triangle's edge", dc::vermillion);
  d.legend_note("15 rows x 17 columns = 255 samples: the count is the a8 byte, " +
                std::to_string(count) + "/255 = " + decimal3(count / 255.0) + ".");
  d.legend_note("Exact area (step 1): " + decimal3(exact) + " = " + decimal3(exact * 255) +
                "/255; cut to 8 bits, as AGG stores it: " +
                std::to_string(static_cast<int>(std::floor(exact * 255))) + "/255.");
  d.legend_note("Samples decided here by chapter 07's exact rule, at pixman's positions.");
  return {"09_step7_pixman_grid", d.svg()};
}

// Two decimals without the leading zero ("0.25" -> ".25", "-0.5" -> "-.50"), to fit a cell.
std::string short_decimal(double v) {
  char text[16];
  std::snprintf(text, sizeof text, "%.2f", v);
  std::string s = text;
  if (s.rfind("0.", 0) == 0) s.erase(0, 1);
  if (s.rfind("-0.", 0) == 0) s.erase(1, 1);
  return s == "-.00" ? ".00" : s;
}

tri::SvgFigure row_cells_figure() {
  // Row 0 of a counter-clockwise triangle whose two slanted edges cross it: what each cell gets.
  const tri::Triangle t = {{{0.75, -2.5}, {6.25, -2.5}, {2.5, 3.5}}};
  tri::ch09::RowCells cells;
  cells.start_row(8);
  tri::ch09::add_edges_in_row(cells, t, 0);
  tri::PixelDiagram d({0, -1}, {7, 1},
                      "One pixel row of cells: each keeps an area, and passes a cover on", 72);
  d.show_centres(false);
  double cover = 0;
  for (int x = 0; x <= 7; ++x) {
    cover += cells.cover(x);
    const double coverage = -(cover + cells.area(x));
    d.fill({x, 0}, shade(coverage));
    d.label({x - 0.45, 0.28}, "a " + short_decimal(cells.area(x)), LabelPlace::right);
    d.label({x - 0.45, 0.0}, "c " + short_decimal(cover), LabelPlace::right);
    d.label({x - 0.45, -0.28}, "= " + short_decimal(coverage), LabelPlace::right);
  }
  d.frame({0, 0}, {7, 0}, dc::black, 2.5);
  d.triangle(t[0], t[1], t[2], dc::vermillion);
  d.legend_fill("row 0, shaded by coverage", shade(0.6));
  d.legend_line("the triangle, counter-clockwise", dc::vermillion);
  d.legend_note("a: what a cell keeps, the signed height of the edge piece inside it times the");
  d.legend_note("distance from the piece to the cell's right side. c: the signed heights of all");
  d.legend_note("pieces left of the cell. The left edge runs down (height -1), the right edge up");
  d.legend_note("(+1): c is -1 between them, 0 outside. Coverage (=) is -(c + a).");
  return {"09_row_cells", d.svg()};
}

// One mesh drawn with coverage summed or composited over, the inside's pixels labelled in percent
// wherever they are not full.
tri::PixelDiagram mesh_panel(const std::vector<tri::Triangle>& mesh, tri::ch09::Blend blend,
                             const std::string& title) {
  tri::ch09::CoverageCanvas canvas(14, 10);
  tri::ch09::RowCells cells;
  for (const auto& t : mesh) tri::ch09::draw_triangle_area(canvas, t, cells, blend);
  tri::PixelDiagram d({0, 0}, {13, 9}, title, 30);
  d.show_centres(false);
  int below = 0;
  float lowest = 1;
  for (int y = 0; y <= 9; ++y) {
    for (int x = 0; x <= 13; ++x) {
      const float v = canvas.at(x, y);
      d.fill({x, y}, shade(std::min(1.0f, v)));
      const bool inside = x >= 1 && x <= 12 && y >= 1 && y <= 8;
      if (inside && v < 0.995f) {
        d.pixel_text({x, y}, std::to_string(static_cast<int>(std::lround(v * 100))));
        ++below;
        lowest = std::min(lowest, v);
      }
    }
  }
  for (const auto& t : mesh) d.triangle(t[0], t[1], t[2], dc::vermillion, 1);
  d.legend_fill("shade = coverage of the pixel (full: 100%)", shade(1));
  d.legend_line("the mesh's edges", dc::vermillion);
  d.legend_note(below == 0
                    ? std::string("Every inner pixel is full.")
                    : std::to_string(below) + " of 96 inner pixels are not full; the lowest is " +
                          std::to_string(static_cast<int>(std::lround(lowest * 100))) + "%.");
  return d;
}

tri::SvgFigure conflation_figure() {
  const auto mesh = tri::ch07::jittered_mesh(3, 2, {0.5, 0.5}, 4, 0.15, 3);
  const std::array<tri::PixelDiagram, 2> panels = {
      mesh_panel(mesh, tri::ch09::Blend::sum, "Coverage summed"),
      mesh_panel(mesh, tri::ch09::Blend::over, "Coverage composited as alpha (over)")};
  return {"09_conflation",
          tri::side_by_side(panels,
                            "A mesh of 12 triangles, anti-aliased two ways: seams where "
                            "edges are shared")};
}

}  // namespace

int main(int argc, char** argv) {
  return tri::run_chapter_program(
      argc, argv, "09_anti_aliasing",
      "Chapter 09, how much of each pixel: exact coverage, samples, row cells, seams.",
      {exact_coverage_figure, step1_edge_parts_figure, step2_supersampling_figure,
       sample_patterns_figure, row_cells_figure, step4_pixel_pieces_figure, conflation_figure,
       step7_pixman_grid_figure});
}
