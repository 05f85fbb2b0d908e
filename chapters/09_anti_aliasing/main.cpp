// Chapter 09's figures: how much of each pixel a triangle covers, exactly, as diagrams.
#include <array>
#include <cmath>
#include <cstdio>
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
  d.legend_fill("shade = fraction of samples inside", shade(0.5));
  d.legend_line("the triangle's edge", dc::vermillion);
  d.legend_note("Numbers: samples inside, on the pixels the edge crosses.");
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
      {exact_coverage_figure, sample_patterns_figure, row_cells_figure, conflation_figure});
}
