// Chapter 03's figures: each step of Gambetta's DrawFilledTriangle on the hand triangle, his
// Figure 7-3 (the fill with the outline on top), and the traps of the C++ port, as diagrams.
#include "chapters/03_interpolate_fill/check_figures.hpp"
#include "chapters/03_interpolate_fill/step_figures.hpp"
#include "common/figures.hpp"

int main(int argc, char** argv) {
  using namespace tri::ch03::figures;
  return tri::run_chapter_program(
      argc, argv, "03_interpolate_fill",
      "Chapter 03, Gambetta's filled triangle, as SVG pixel diagrams: one per step on the hand\n"
      "triangle (03_step1_sorted.svg ... 03_step5_spans.svg), Figure 7-3 with the outline on\n"
      "top of the fill, upright and flipped (03_figure_7_3.svg, 03_figure_7_3_flipped.svg,\n"
      "03_figure_7_3_close_up.svg), tinyrenderer's triangles filled and outlined\n"
      "(03_tinyrenderer_fill_outline.svg, 03_tinyrenderer_fill_outline_close_up.svg) and the\n"
      "port's traps (03_trap_one_short.svg, 03_trap_no_pop_back.svg).",
      [](tri::FigureWriter& figures) {
        figures.save_svg("03_step1_sorted", step1_sorted());
        figures.save_svg("03_step2_edges", step2_edges());
        figures.save_svg("03_step3_concatenate", step3_concatenate());
        figures.save_svg("03_step4_left_right", step4_left_right());
        figures.save_svg("03_step5_spans", step5_spans());
        figures.save_svg("03_figure_7_3", figure_7_3(1));
        figures.save_svg("03_figure_7_3_flipped", figure_7_3(-1));
        figures.save_svg("03_figure_7_3_close_up", figure_7_3_close_up());
        figures.save_svg("03_tinyrenderer_fill_outline", tinyrenderer_fill_outline());
        figures.save_svg("03_tinyrenderer_fill_outline_close_up",
                         tinyrenderer_fill_outline_close_up());
        figures.save_svg("03_trap_one_short", trap_one_short());
        figures.save_svg("03_trap_no_pop_back", trap_no_pop_back());
      });
}
