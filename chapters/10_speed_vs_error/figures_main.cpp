// Chapter 10's deterministic figures, apart from the timed report: the timing plan on a scripted
// clock (10_timing_plan.svg) and the two speeds from the committed quick snapshot
// (10_two_speeds.svg), so that both can be compared with their committed copies.
#include "chapters/10_speed_vs_error/timing_figure.hpp"
#include "chapters/10_speed_vs_error/two_speeds_figure.hpp"
#include "common/figures.hpp"
#include "measure/snapshot_reading.hpp"

int main(int argc, char** argv) {
  return tri::run_chapter_program(
      argc, argv, "10_speed_vs_error_figures",
      "Chapter 10's figures that no timed run makes: the timing plan of the quick setting run\n"
      "on a scripted clock (10_timing_plan.svg), and the two speeds of a few algorithms beside\n"
      "the write ceiling, drawn from the committed snapshot " TUTORIAL_QUICK_SNAPSHOT
      "\n(10_two_speeds.svg).",
      {tri::ch10::timing_plan_figure,
       [] { return tri::ch10::two_speeds_figure(tri::read_snapshot(TUTORIAL_QUICK_SNAPSHOT)); }});
}
