// Chapter 10's figures: how much of each pixel a triangle covers, exactly, as diagrams.
#include <string>

#include "chapters/10_coverage/area_oracle.hpp"
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
std::string percent(const tri::ch10::Fraction& coverage) {
  const auto whole = static_cast<int>(coverage.numerator() * 100 / coverage.denominator());
  return whole == 0 ? "<1" : std::to_string(whole);
}

tri::SvgFigure exact_coverage_figure() {
  const tri::Triangle t = {{{1.25, 0.75}, {10.5, 2.375}, {4.0, 7.25}}};
  tri::PixelDiagram d({0, 0}, {12, 8},
                      "Exact coverage: the part of each pixel square inside the triangle", 40);
  d.show_centres(false);  // the squares matter here, not their centres
  for (const auto& p : tri::ch10::exact_coverages(t)) {
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
  const tri::ch10::Fraction area = tri::ch10::exact_area(t);
  d.legend_note("Numbers: percent of the pixel covered, rounded down. All the coverages add up");
  d.legend_note("to the triangle's area, " + area.text() + " = " +
                std::to_string(area.to_double()).substr(0, 8) + " pixels, exactly.");
  return {"10_exact_coverage", d.svg()};
}

}  // namespace

int main(int argc, char** argv) {
  return tri::run_chapter_program(
      argc, argv, "10_coverage",
      "Chapter 10, how much of each pixel: the exact coverage of every pixel a triangle touches\n"
      "(10_exact_coverage.svg).",
      {exact_coverage_figure});
}
