/// @file
/// The one way the book times code (docs/DESIGN.md section 8): a warm-up, repetitions calibrated
/// so that one sample lasts long enough to trust, samples taken in interleaved rounds across the
/// things compared, then the median and spread of the samples. Chapter 08's benchmark, chapter
/// 10's report and `raster --bench` all time through here.
#pragma once

#include <chrono>
#include <functional>
#include <span>
#include <vector>

#include "measure/statistics.hpp"

namespace tri {

/// How each timed sample is taken.
struct TimingPlan {
  double min_sample_seconds =
      0.01;                       ///< repetitions per sample are raised until a sample lasts this
  int samples = 5;                ///< timed samples after the warm-up (the median is of these)
  int max_repetitions = 1 << 20;  ///< never more runs per sample than this
  int repetitions = 0;            ///< runs per sample, fixed (no calibration); 0: calibrate
};

/// The outcome of timing one piece of work.
struct Timing {
  Spread seconds;       ///< seconds per run: median, fastest and slowest sample
  int repetitions = 0;  ///< runs per sample
  int samples = 0;      ///< timed samples
};

/// The clock a timing reads. The book times on steady_clock (steady_now, the default); a test or
/// a figure passes a scripted clock to see what the timing does with durations it chose.
using TimingClock = std::function<std::chrono::steady_clock::time_point()>;

/// steady_clock's now(): the book's one clock.
std::chrono::steady_clock::time_point steady_now() noexcept;

/// Seconds that `repetitions` calls of run() take on `clock`.
double seconds_of(const std::function<void()>& run, int repetitions = 1,
                  const TimingClock& clock = steady_now);

/// Times run(): time_interleaved with nothing else to interleave.
Timing time_runs(const std::function<void()>& run, const TimingPlan& plan,
                 const TimingClock& clock = steady_now);

/// Times several pieces of work against each other. Each is warmed up by one untimed run and gets
/// its own repetitions per sample (raised until a sample lasts plan.min_sample_seconds, capped by
/// plan.max_repetitions; the calibration runs warm up too; plan.repetitions fixes them instead).
/// Then plan.samples rounds each take one sample of every run in turn, so that whatever else the
/// machine does slows them all alike. Each sample's time is divided by its repetitions.
/// after_round, if set, hears how many rounds are done. Every batch is timed on `clock`.
std::vector<Timing> time_interleaved(std::span<const std::function<void()>> runs,
                                     const TimingPlan& plan,
                                     const std::function<void(int rounds_done)>& after_round = {},
                                     const TimingClock& clock = steady_now);

/// Repetitions to try next during calibration: enough to reach the target by the last sample's
/// speed (with 20% to spare), at least double, at most max_repetitions.
int next_repetitions(int repetitions, double elapsed_seconds, double target_seconds,
                     int max_repetitions) noexcept;

/// Millions of pixels per second: pixels / seconds / 1e6, or 0 when no time was measured.
double mpix_per_second(double pixels, double seconds) noexcept;

}  // namespace tri
