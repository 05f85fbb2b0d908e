// Chapter 04's figures: each step of tinyrenderer's scanline fill on the article's green
// triangle, where the loop variants part ways, and the pixels the int casts add, as diagrams.
#include "chapters/04_scanline/check_figures.hpp"
#include "chapters/04_scanline/step_figures.hpp"
#include "common/figures.hpp"

int main(int argc, char** argv) {
  using namespace tri::ch04::figures;
  return tri::run_chapter_program(
      argc, argv, "04_scanline",
      "Chapter 04, scanline fill (tinyrenderer lesson 2), as SVG pixel diagrams of the\n"
      "article's green triangle after each step: 04_outlines, 04_sorted_boundaries,\n"
      "04_lower_half_points, 04_lower_half_filled, 04_two_loops, 04_single_loop; then\n"
      "04_loop_differences (the pixels where the loop variants differ, zoomed),\n"
      "04_loop_differences_red_white (the same on the other two triangles) and\n"
      "04_truncation_close_up (pixels the int casts add to the red triangle).",
      {outlines, sorted_boundaries, lower_half_points, lower_half_filled, two_loops, single_loop,
       loop_differences, loop_differences_red_white, truncation_close_up});
}
