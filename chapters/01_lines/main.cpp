// Chapter 01's figures: the star of lines in every octant, a diagram of the tie steps where the
// four algorithms part ways on it, and one diagram per algorithm of lines with ties drawn both
// ways.
#include <algorithm>
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "chapters/01_lines/line_algorithms.hpp"
#include "chapters/01_lines/line_steps.hpp"
#include "common/figures.hpp"
#include "common/pixel_diagram.hpp"

namespace {

using namespace tri;
using namespace tri::ch01;
namespace dc = tri::diagram_colors;

constexpr glm::ivec2 star_centre{32, 32};
constexpr int star_radius = 30;
constexpr int star_spoke_count = 24;

// One tie step of the star: the two candidate pixels and which algorithms drew each.
struct StarTie {
  Segment spoke;
  glm::ivec2 up;                    // the exact reference's choice: the tie rounded up
  glm::ivec2 other;                 // the other candidate
  std::string drew_up, drew_other;  // initials of the algorithms that drew each
};

std::vector<StarTie> star_ties() {
  std::vector<StarTie> ties;
  for (const Segment& spoke : tri::ch01::star_spokes(star_centre, star_radius, star_spoke_count)) {
    std::vector<std::vector<tri::ch01::LineStep>> runs;
    for (const LineAlgorithm& algorithm : line_algorithms) {
      runs.push_back(tri::ch01::steps_against_exact(algorithm.draw, spoke[0], spoke[1]));
    }
    for (std::size_t step = 0; step < runs[0].size(); ++step) {
      const auto& exact = runs[0][step].exact;
      if (!exact.tie) continue;
      const bool x_major = std::abs(spoke[1].x - spoke[0].x) >= std::abs(spoke[1].y - spoke[0].y);
      StarTie tie{spoke, exact.pixel, exact.pixel - (x_major ? glm::ivec2(0, 1) : glm::ivec2(1, 0)),
                  "", ""};
      for (std::size_t a = 0; a < line_algorithms.size(); ++a) {
        const char initial = static_cast<char>(line_algorithms[a].name[0] - 'a' + 'A');
        (runs[a][step].drawn == tie.up ? tie.drew_up : tie.drew_other) += initial;
      }
      ties.push_back(tie);
    }
  }
  return ties;
}

// Every pixel that all four algorithms draw, per spoke (the spokes alternate two colours).
void fill_agreed_star(PixelDiagram& diagram, tri::Color even, tri::Color odd) {
  const auto spokes = tri::ch01::star_spokes(star_centre, star_radius, star_spoke_count);
  for (std::size_t i = 0; i < spokes.size(); ++i) {
    std::vector<tri::ch01::LineStep> first;
    std::vector<bool> agreed;
    for (const LineAlgorithm& algorithm : line_algorithms) {
      const auto steps = tri::ch01::steps_against_exact(algorithm.draw, spokes[i][0], spokes[i][1]);
      if (first.empty()) {
        first = steps;
        agreed.assign(steps.size(), true);
      }
      for (std::size_t s = 0; s < steps.size(); ++s) {
        agreed[s] = agreed[s] && steps[s].drawn == first[s].drawn;
      }
    }
    for (std::size_t s = 0; s < first.size(); ++s) {
      if (agreed[s]) diagram.fill(first[s].drawn, i % 2 == 0 ? even : odd);
    }
  }
}

constexpr glm::ivec2 zoom_first{16, 16}, zoom_last{48, 48};

tri::SvgFigure star_figure() {
  const std::vector<StarTie> ties = star_ties();
  PixelDiagram diagram({0, 0}, {64, 64},
                       "24 spokes from (32, 32), 15° apart: the four algorithms differ only at "
                       "6 tie steps",
                       8);
  diagram.show_centres(false);
  fill_agreed_star(diagram, dc::blue, dc::sky_blue);
  int split = 0;
  for (const StarTie& tie : ties) {
    if (tie.drew_up.size() == line_algorithms.size()) continue;  // all four agree
    ++split;
    diagram.fill(tie.up, dc::orange);
    diagram.fill(tie.other, dc::orange);
  }
  for (const Segment& spoke : tri::ch01::star_spokes(star_centre, star_radius, star_spoke_count)) {
    diagram.line(spoke[0], spoke[1], dc::black, 0.8);
  }
  diagram.frame(zoom_first, zoom_last, dc::vermillion, 1.5, true);
  diagram.vertex(star_centre, "centre", tri::LabelPlace::below_right);
  diagram.legend_fill("drawn by all four algorithms (spokes alternate two blues)", dc::blue);
  diagram.legend_fill("tie step where they differ: each of the two pixels is drawn by some",
                      dc::orange);
  diagram.legend_line("ideal segments, from the centre to the tips", dc::black);
  diagram.legend_line("the region zoomed in 01_star_differences", dc::vermillion, true);
  diagram.legend_note("Spokes end at the pixel nearest to radius 30; " + std::to_string(split) +
                      " of the " + std::to_string(ties.size()) +
                      " tie steps split the algorithms, 2 against 2.");
  return tri::SvgFigure{"01_star", diagram.svg()};
}

tri::SvgFigure star_differences_figure() {
  const std::vector<StarTie> ties = star_ties();
  PixelDiagram diagram(zoom_first, zoom_last,
                       "The star's 8 tie steps: which pixel each algorithm draws "
                       "(G Gambetta, D DDA, B Bresenham, M midpoint)",
                       22);
  fill_agreed_star(diagram, dc::light_gray, dc::light_gray);
  for (const StarTie& tie : ties) {
    diagram.fill(tie.up, dc::orange);
    if (!tie.drew_other.empty()) diagram.fill(tie.other, dc::sky_blue);
    for (const glm::ivec2 p : {tie.up, tie.other}) diagram.mark(p, PixelMark::square);
    diagram.pixel_text(tie.up, tie.drew_up.size() == line_algorithms.size() ? "all" : tie.drew_up);
    diagram.pixel_text(tie.other, tie.drew_other);
  }
  for (const Segment& spoke : tri::ch01::star_spokes(star_centre, star_radius, star_spoke_count)) {
    diagram.line(spoke[0], spoke[1], dc::dark_gray, 1);
  }
  for (const StarTie& tie : ties) {
    const auto part = tri::clip_to_pixels(tie.spoke[0], tie.spoke[1], zoom_first, zoom_last);
    diagram.line((*part)[0], (*part)[1], dc::black, 2);
    const glm::dvec2 out = (*part)[1];
    const bool right = out.x > star_centre.x, top = out.y > star_centre.y;
    diagram.label(out, "to " + point_text(tie.spoke[1]),
                  top ? (right ? tri::LabelPlace::below_left : tri::LabelPlace::below_right)
                      : (right ? tri::LabelPlace::above_left : tri::LabelPlace::above_right));
  }
  diagram.vertex(star_centre, "centre", tri::LabelPlace::below_right);
  diagram.legend_fill("tie: the pixel rounded up (nearest pixel of the reference)", dc::orange);
  diagram.legend_fill("tie: the pixel rounded down", dc::sky_blue);
  diagram.legend_mark("the two candidates of a tie (line exactly halfway)", PixelMark::square);
  diagram.legend_fill("drawn by all four", dc::light_gray);
  diagram.legend_line("ideal spoke with a tie", dc::black);
  diagram.legend_line("other ideal spokes", dc::dark_gray);
  diagram.legend_note(
      "Letters in a pixel: the algorithms that draw it (all: all four). Each spoke "
      "with a tie runs 26 by 15 pixels,");
  diagram.legend_note("so 13 steps out its minor coordinate is exactly 7.5 from the centre's.");
  return tri::SvgFigure{"01_star_differences", diagram.svg()};
}

// Lines whose exact path passes halfway between two pixels at some steps. Each is drawn twice:
// from its left end in the upper copy (moved up 16 rows), from its right end in the lower one.
struct TieLine {
  Segment ends;  // left end first
  std::string slope;
  glm::dvec2 slope_at;  // where the slope is written, in the upper copy
  tri::LabelPlace slope_place;
  std::array<tri::LabelPlace, 2> from_place;  // label of the start, upper copy then lower copy
};
const std::array<TieLine, 4> tie_lines{{
    {{{{1, 1}, {13, 2}}},
     "dy/dx = 1/12",
     {4, 19},
     tri::LabelPlace::right,
     {tri::LabelPlace::below_right, tri::LabelPlace::below_left}},
    {{{{1, 8}, {13, 14}}},
     "dy/dx = 1/2",
     {-0.3, 28},
     tri::LabelPlace::right,
     {tri::LabelPlace::below_right, tri::LabelPlace::right}},
    {{{{15, 1}, {18, 13}}},
     "dx/dy = 1/4",
     {15.6, 22},
     tri::LabelPlace::left,
     {tri::LabelPlace::below_left, tri::LabelPlace::above_right}},
    {{{{20, 13}, {22, 1}}},
     "dx/dy = -1/6",
     {22.3, 23},
     tri::LabelPlace::right,
     {tri::LabelPlace::above_left, tri::LabelPlace::below_left}},
}};
constexpr int upper_shift = 16;

tri::SvgFigure ties_figure(const LineAlgorithm& algorithm) {
  PixelDiagram diagram({0, 0}, {29, 30},
                       "Ties drawn by " + std::string(algorithm.name) +
                           ": upper copy from the left end, lower copy from the right end",
                       22);
  int not_rounded_up = 0, ties = 0;
  for (const bool upper : {true, false}) {
    const glm::ivec2 shift(0, upper ? upper_shift : 0);
    for (const TieLine& line : tie_lines) {
      const glm::ivec2 left = line.ends[0] + shift, right = line.ends[1] + shift;
      const auto [from, to] = upper ? std::pair(left, right) : std::pair(right, left);
      const bool x_major = std::abs(to.x - from.x) >= std::abs(to.y - from.y);
      const glm::ivec2 down = x_major ? glm::ivec2(0, 1) : glm::ivec2(1, 0);
      for (const auto& step : tri::ch01::steps_against_exact(algorithm.draw, from, to)) {
        if (step.drawn == step.exact.pixel) {
          diagram.fill(step.drawn, dc::covered);
        } else {
          diagram.fill(step.drawn, dc::vermillion);
          diagram.mark(step.exact.pixel, PixelMark::cross);
          ++not_rounded_up;
        }
        if (step.exact.tie) {
          ++ties;
          diagram.mark(step.exact.pixel, PixelMark::ring, dc::blue);
          diagram.mark(step.exact.pixel - down, PixelMark::ring, dc::blue);
        }
      }
      diagram.line(from, to, dc::blue, 2);
      diagram.vertex(from, "from", line.from_place[upper ? 0 : 1]);
      diagram.point(to, dc::black);
      if (upper) diagram.label(line.slope_at, line.slope, line.slope_place, dc::dark_gray);
    }
  }
  diagram.label({-0.3, 15.5},
                "upper copy (rows 17-30): from the left end;  "
                "lower copy (rows 1-14): the same lines from the right end",
                tri::LabelPlace::right);
  diagram.legend_fill("drawn, the nearest pixel (a tie rounded up)", dc::covered);
  diagram.legend_fill("drawn, not rounded up (only at a tie)", dc::vermillion);
  diagram.legend_mark("rounded-up pixel, not drawn", PixelMark::cross);
  diagram.legend_mark("tie: the two candidates", PixelMark::ring, dc::blue);
  diagram.legend_line("ideal segment (from the labelled end to the dot)", dc::blue);
  diagram.legend_note(std::to_string(ties) + " tie steps, " + std::to_string(not_rounded_up) +
                      " not rounded up. Up means toward larger y for a shallow line and larger x "
                      "for a steep one.");
  return tri::SvgFigure{"01_ties_" + std::string(algorithm.name), diagram.svg()};
}

// The star, its tie steps, then one ties diagram per algorithm.
std::vector<tri::SvgFigureFunction> figures() {
  std::vector<tri::SvgFigureFunction> list{star_figure, star_differences_figure};
  for (const LineAlgorithm& algorithm : line_algorithms) {
    list.push_back([&algorithm] { return ties_figure(algorithm); });
  }
  return list;
}

}  // namespace

int main(int argc, char** argv) {
  return tri::run_chapter_program(
      argc, argv, "01_lines",
      "Chapter 01, lines: the star and the tie diagrams of the four line algorithms.", figures());
}
