// No test here reads a clock's value: the timing code is checked by what it runs and fills.
#include <algorithm>

#include <catch2/catch.hpp>

#include "chapters/09_speed_vs_error/timing.hpp"

using tri::Canvas;
using tri::ch09::next_repetitions;
using tri::ch09::Timing;
using tri::ch09::TimingPlan;

TEST_CASE("Calibration aims past the target, at least doubles, and stops at the cap", "[timing]") {
  // 1 run took 1 ms, the target is 10 ms: 1.2 * 10 = 12 runs.
  CHECK(next_repetitions(1, 0.001, 0.01, 1000) == 12);
  // Nearly there: still at least double.
  CHECK(next_repetitions(10, 0.009, 0.01, 1000) == 20);
  // Below the clock's resolution: ten times more.
  CHECK(next_repetitions(3, 0.0, 0.01, 1000) == 30);
  CHECK(next_repetitions(600, 0.001, 0.01, 1000) == 1000);
}

TEST_CASE("A zero target times one warm-up, one calibration and the samples, one run each",
          "[timing]") {
  int runs = 0;
  const Timing timing = tri::ch09::time_runs([&] { ++runs; }, TimingPlan{0.0, 3, 100});
  CHECK(runs == 1 + 1 + 3);
  CHECK(timing.repetitions == 1);
  CHECK(timing.samples == 3);
  CHECK(timing.seconds.min <= timing.seconds.median);
  CHECK(timing.seconds.median <= timing.seconds.max);
}

TEST_CASE("Calibration never runs more than the cap per sample", "[timing]") {
  int runs = 0;
  // An hour per sample is never reached: the first guess jumps to the cap of 8, which ends the
  // calibration.
  const Timing timing = tri::ch09::time_runs([&] { ++runs; }, TimingPlan{3600.0, 2, 8});
  CHECK(timing.repetitions == 8);
  CHECK(timing.samples == 2);
  CHECK(runs == 1 + (1 + 8) + 2 * 8);
}

TEST_CASE("The fill ceiling fills every pixel of the canvas, in one thread or several",
          "[timing]") {
  for (const int threads : {1, 3, 64}) {
    Canvas canvas(7, 5, tri::colors::black);
    tri::ch09::time_canvas_fill(canvas, threads, TimingPlan{0.0, 2, 1});
    const auto pixels = canvas.pixels();
    CHECK(pixels.front() != tri::colors::black);
    CHECK(std::all_of(pixels.begin(), pixels.end(),
                      [&](tri::Color c) { return c == pixels.front(); }));
    CHECK(canvas.outside_writes() == 0);
  }
}

TEST_CASE("Mpixels per second divide pixels by seconds, and no time gives 0", "[timing]") {
  CHECK(tri::ch09::mpix_per_second(2e6, 0.5) == 4.0);
  CHECK(tri::ch09::mpix_per_second(2e6, 0.0) == 0.0);
}
