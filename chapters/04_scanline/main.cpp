// Chapter 04's figures: each step of tinyrenderer's scanline fill on the article's green
// triangle, where the loop variants part ways, and the pixels the int casts add, as diagrams.
#include "chapters/04_scanline/check_figures.hpp"
#include "chapters/04_scanline/step_figures.hpp"
#include "common/figures.hpp"

int main(int argc, char** argv) {
  using namespace tri::ch04::figures;
  return tri::run_chapter_program(
      argc, argv, "04_scanline",
      "Chapter 04, tinyrenderer's scanline fill: one diagram per step and where loops differ.",
      {outlines, sorted_boundaries, lower_half_points, lower_half_filled, two_loops, single_loop,
       loop_differences, loop_differences_red_white, truncation_close_up});
}
