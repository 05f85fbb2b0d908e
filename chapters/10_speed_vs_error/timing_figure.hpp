/// @file
/// Step 2's figure: the timing plan as measure/timing.cpp runs it, on a scripted clock, so that
/// the same durations give the same figure on every run.
#pragma once

#include <functional>
#include <vector>

#include "common/figures.hpp"
#include "measure/timing.hpp"

namespace tri::ch10 {

/// One batch of draws the timing code ran, as its clock saw it.
struct TimedBatch {
  enum class Stage { warm_up, calibration, sample };
  Stage stage = Stage::warm_up;
  int draws = 0;
  double seconds = 0;
};

/// What the timing code did with scripted durations: its batches in order, and its result.
struct TimingTrace {
  std::vector<TimedBatch> batches;
  Timing timing;
};

/// Seconds one scripted draw takes, given how many draws came before it and when it starts.
using DrawScript = std::function<double(int draw, double start_seconds)>;

/// Runs time_runs with `plan` on a clock that only the draws move, each by what `script` says;
/// the batches are read off the clock: the draws before its first reading are the warm-up, then
/// each pair of readings is one batch, the last timing.samples of them the samples.
TimingTrace trace_timing(const TimingPlan& plan, const DrawScript& script);

/// The figure's script, in milliseconds: draws settle from 2.5 ms to about 1 ms (caches, clock
/// frequency), wobble by up to 0.03 ms (seeded), and the first draw that starts after 50 ms waits
/// 4 ms for another process.
double settling_draw_seconds(int draw, double start_seconds);

/// The figure: the quick setting's plan on settling_draw_seconds, one bar per batch (warm-up,
/// calibration, samples) against the target, each sample's time per draw, the median marked.
SvgFigure timing_plan_figure();

}  // namespace tri::ch10
