#include "chapters/10_speed_vs_error/timing_figure.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <string>

#include "chapters/10_speed_vs_error/figure_parts.hpp"
#include "chapters/10_speed_vs_error/suites.hpp"
#include "common/printable_text.hpp"
#include "common/random.hpp"
#include "measure/plot/plot_frame.hpp"
#include "measure/plot/svg_elements.hpp"

namespace tri::ch10 {
namespace {

using Clock = std::chrono::steady_clock;
namespace fp = figure_parts;

double seconds_since(Clock::time_point start, Clock::time_point t) {
  return std::chrono::duration<double>(t - start).count();
}

std::string milliseconds(double seconds, int decimals) {
  return fp::fixed(seconds * 1e3, decimals) + " ms";
}

std::string draws_text(int draws) {
  return std::to_string(draws) + (draws == 1 ? " draw" : " draws");
}

}  // namespace

TimingTrace trace_timing(const TimingPlan& plan, const DrawScript& script) {
  const Clock::time_point start{};
  Clock::time_point now = start;
  int draws = 0;
  struct Reading {
    Clock::time_point time;
    int draws;
  };
  std::vector<Reading> readings;
  const auto draw = [&] {
    const double seconds = script(draws, seconds_since(start, now));
    now += std::chrono::nanoseconds(std::llround(seconds * 1e9));
    ++draws;
  };
  const auto clock = [&] {
    readings.push_back({now, draws});
    return now;
  };
  TimingTrace trace;
  trace.timing = time_runs(draw, plan, clock);
  if (readings.empty()) return trace;
  trace.batches.push_back({TimedBatch::Stage::warm_up, readings.front().draws,
                           seconds_since(start, readings.front().time)});
  const std::size_t batches = readings.size() / 2;
  const std::size_t samples = static_cast<std::size_t>(std::max(0, trace.timing.samples));
  for (std::size_t b = 0; b < batches; ++b) {
    const Reading& first = readings[2 * b];
    const Reading& last = readings[2 * b + 1];
    const auto stage =
        b + samples >= batches ? TimedBatch::Stage::sample : TimedBatch::Stage::calibration;
    trace.batches.push_back(
        {stage, last.draws - first.draws, seconds_since(first.time, last.time)});
  }
  return trace;
}

double settling_draw_seconds(int draw, double start_seconds) {
  double settling = 1.5;
  for (int i = 0; i < draw; ++i) settling *= 0.55;
  Random wobble(1000 + static_cast<std::uint64_t>(draw));
  double milliseconds = 1.0 + settling + wobble.real(-0.03, 0.03);
  const double start_ms = start_seconds * 1e3;
  if (start_ms <= 50 && 50 < start_ms + milliseconds) milliseconds += 4;  // another process runs
  return milliseconds / 1e3;
}

SvgFigure timing_plan_figure() {
  const TimingPlan plan = bench_settings(SuiteSize::quick).timing;
  const TimingTrace trace = trace_timing(plan, settling_draw_seconds);
  const double target = plan.min_sample_seconds;

  constexpr double width = 760, left = 70;
  const PlotBox box{left, width - 30, 104, 304};
  double highest = target;
  for (const TimedBatch& b : trace.batches) highest = std::max(highest, b.seconds);
  const double axis_ms = 5 * std::ceil(highest * 1.25e3 / 5);
  const auto y_of = [&](double seconds) {
    return box.bottom - (box.bottom - box.top) * seconds * 1e3 / axis_ms;
  };
  const double slot = (box.right - box.left) / static_cast<double>(trace.batches.size());
  const double bar = slot * 0.56;
  const auto centre_of = [&](std::size_t i) { return box.left + slot * (i + 0.5); };

  // The median sample is the one whose time per draw the timing reports (odd sample counts).
  std::size_t median_batch = trace.batches.size();
  for (std::size_t i = 0; i < trace.batches.size(); ++i) {
    const TimedBatch& b = trace.batches[i];
    if (b.stage == TimedBatch::Stage::sample && median_batch == trace.batches.size() &&
        b.seconds / b.draws == trace.timing.seconds.median) {
      median_batch = i;
    }
  }

  std::ostringstream svg;
  const double height = box.bottom + 196;
  open_plot(svg, width, height, left,
            "Timing one scene: warm-up, calibrated batches, samples, their median",
            "The quick setting's plan, run by time_runs on a scripted clock: batches of at least " +
                milliseconds(target, 0) + ", " + std::to_string(trace.timing.samples) + " samples",
            "Scripted draws: about 2.5 ms at first, settling to about 1 ms; another process takes "
            "the core for 4 ms during one draw.");
  open_group(svg, {{"stroke", "#ddd"}});
  for (double ms = 5; ms <= axis_ms; ms += 5) {
    line(svg, box.left, y_of(ms / 1e3), box.right, y_of(ms / 1e3));
  }
  close_group(svg);
  open_group(svg, {{"text-anchor", "end"}});
  for (double ms = 0; ms <= axis_ms; ms += 5) {
    element(svg, "text", {{"x", box.left - 6}, {"y", y_of(ms / 1e3) + 4}}, fp::fixed(ms, 0));
  }
  close_group(svg);
  y_axis_title(svg, box, 40, "milliseconds a batch took");

  open_group(svg, {{"text-anchor", "middle"}});
  for (std::size_t i = 0; i < trace.batches.size(); ++i) {
    const TimedBatch& b = trace.batches[i];
    const bool warm_up = b.stage == TimedBatch::Stage::warm_up;
    const bool sample = b.stage == TimedBatch::Stage::sample;
    const char* fill = warm_up ? fp::grey : sample ? fp::blue : fp::sky_blue;
    const double x = centre_of(i), top = y_of(b.seconds);
    element(svg, "rect",
            {{"x", x - bar / 2},
             {"y", top},
             {"width", bar},
             {"height", box.bottom - top},
             {"fill", fill},
             {"stroke", i == median_batch ? fp::vermillion : "none"},
             {"stroke-width", 3.0}});
    element(svg, "text", {{"x", x}, {"y", top - 6}}, milliseconds(b.seconds, 2));
    if (sample) {
      element(svg, "text", {{"x", x}, {"y", top - 20}, {"font-weight", "bold"}},
              "÷" + std::to_string(b.draws) + " = " + milliseconds(b.seconds / b.draws, 3));
    }
    if (i == median_batch) {
      element(svg, "text",
              {{"x", x}, {"y", top - 34}, {"fill", fp::vermillion}, {"font-weight", "bold"}},
              "median");
    }
    element(svg, "text", {{"x", x}, {"y", box.bottom + 16}}, draws_text(b.draws));
  }
  // The three stages named under their bars.
  const auto stage_span = [&](TimedBatch::Stage stage, const std::string& name) {
    std::size_t first = trace.batches.size(), last = 0;
    for (std::size_t i = 0; i < trace.batches.size(); ++i) {
      if (trace.batches[i].stage != stage) continue;
      first = std::min(first, i);
      last = i;
    }
    if (first == trace.batches.size()) return;
    const double from = centre_of(first) - slot / 2 + 6, to = centre_of(last) + slot / 2 - 6;
    line(svg, from, box.bottom + 24, to, box.bottom + 24, {{"stroke", "#555"}});
    element(svg, "text", {{"x", (from + to) / 2}, {"y", box.bottom + 38}, {"font-size", "12"}},
            escape_xml(name));
  };
  stage_span(TimedBatch::Stage::warm_up, "warm-up (untimed)");
  stage_span(TimedBatch::Stage::calibration, "calibration");
  stage_span(TimedBatch::Stage::sample,
             std::to_string(trace.timing.samples) + " samples, in rounds");
  close_group(svg);
  line(svg, box.left, y_of(target), box.right, y_of(target),
       {{"stroke", fp::vermillion}, {"stroke-width", 1.5}, {"stroke-dasharray", "5 3"}});
  line(svg, box.left, box.bottom, box.right, box.bottom, {{"stroke", "black"}});
  line(svg, box.left, box.top, box.left, box.bottom, {{"stroke", "black"}});

  // How each calibration batch led to the next, as next_repetitions decided.
  double y = box.bottom + 64;
  for (std::size_t i = 0; i < trace.batches.size(); ++i) {
    const TimedBatch& b = trace.batches[i];
    if (b.stage != TimedBatch::Stage::calibration) continue;
    std::string text = draws_text(b.draws) + " took " + milliseconds(b.seconds, 2);
    if (b.seconds >= target) {
      text += ", at least " + milliseconds(target, 0) + ": every sample draws " +
              std::to_string(trace.timing.repetitions) + " times.";
    } else {
      const int next = next_repetitions(b.draws, b.seconds, target, plan.max_repetitions);
      text += ", short of " + milliseconds(target, 0) + ": next_repetitions asks for " +
              std::to_string(next) +
              (next == 2 * b.draws ? " (at least double)."
                                   : " (enough for 20% past the target at this speed).");
    }
    element(svg, "text", {{"x", left}, {"y", y}}, escape_xml(text));
    y += 16;
  }

  y += 10;
  fp::legend_swatch(svg, left, y, fp::grey, "warm-up: one draw, not timed");
  fp::legend_swatch(svg, left + 340, y, fp::sky_blue, "calibration batch");
  y += 20;
  fp::legend_swatch(svg, left, y, fp::blue, "sample: a batch of the calibrated draws");
  fp::legend_swatch(svg, left + 340, y, fp::blue, "median sample: its time per draw is the speed",
                    fp::vermillion);
  y += 20;
  fp::legend_dash(svg, left, y, fp::vermillion,
                  "target: a batch must last " + milliseconds(target, 0));
  element(svg, "text", {{"x", left + 340}, {"y", y + 10}},
          "bold: the sample's time divided by its draws");
  svg << "</svg>\n";
  return {"10_timing_plan", svg.str()};
}

}  // namespace tri::ch10
