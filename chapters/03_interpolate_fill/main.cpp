// Chapter 03's figures: each step of Gambetta's DrawFilledTriangle on the hand triangle, his
// Figure 7-3 (the fill with the outline on top), and the traps of the C++ port, as diagrams.
#include "chapters/03_interpolate_fill/check_figures.hpp"
#include "chapters/03_interpolate_fill/step_figures.hpp"
#include "common/figures.hpp"

int main(int argc, char** argv) {
  using namespace tri::ch03::figures;
  return tri::run_chapter_program(
      argc, argv, "03_interpolate_fill",
      "Chapter 03, Gambetta's filled triangle: one diagram per step, Figure 7-3, the traps.",
      {step1_sorted, step2_edges, step3_concatenate, step4_left_right, step5_spans,
       [] { return figure_7_3(1); }, [] { return figure_7_3(-1); }, figure_7_3_close_up,
       tinyrenderer_fill_outline, tinyrenderer_fill_outline_close_up, trap_one_short,
       trap_no_pop_back});
}
