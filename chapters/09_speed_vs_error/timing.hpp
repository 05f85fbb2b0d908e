/// @file
/// Timing with std::chrono::steady_clock: a warm-up, repetitions calibrated so that one sample
/// lasts long enough to trust, then the median and spread of several samples.
#pragma once

#include <functional>

#include "chapters/09_speed_vs_error/statistics.hpp"
#include "chapters/09_speed_vs_error/suites.hpp"
#include "common/canvas.hpp"

namespace tri::ch09 {

/// The outcome of timing one piece of work.
struct Timing {
  Spread seconds;       ///< seconds per run: median, fastest and slowest sample
  int repetitions = 0;  ///< runs per sample
  int samples = 0;      ///< timed samples
};

/// Times run(): one warm-up run, then the repetitions per sample are raised (the calibration
/// runs warm up too) until one sample lasts plan.min_sample_seconds or plan.max_repetitions is
/// reached, then plan.samples samples are timed. Each sample's time is divided by its runs.
Timing time_runs(const std::function<void()>& run, const TimingPlan& plan);

/// Repetitions to try next during calibration: enough to reach the target by the last sample's
/// speed (with 20% to spare), at least double, at most max_repetitions.
int next_repetitions(int repetitions, double elapsed_seconds, double target_seconds,
                     int max_repetitions) noexcept;

/// Times filling every pixel of the canvas with std::fill, in `threads` threads splitting the
/// rows (1: Canvas::clear, which is one std::fill over the pixels; counting must be off).
/// The colour changes with every run so no fill repeats the previous one.
Timing time_canvas_fill(Canvas& canvas, int threads, const TimingPlan& plan);

/// Millions of pixels per second: pixels / seconds / 1e6, or 0 when no time was measured.
double mpix_per_second(double pixels, double seconds) noexcept;

}  // namespace tri::ch09
