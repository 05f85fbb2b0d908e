#include "chapters/09_speed_vs_error/timing.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>
#include <vector>

namespace tri::ch09 {
namespace {

double seconds_for(const std::function<void()>& run, int repetitions) {
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < repetitions; ++i) run();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void fill_rows(Canvas& canvas, int first_row, int end_row, Color color) {
  for (int y = first_row; y < end_row; ++y) {
    const auto row = canvas.row(y);
    std::fill(row.begin(), row.end(), color);
  }
}

}  // namespace

// [listing calibrated_timing]
int next_repetitions(int repetitions, double elapsed_seconds, double target_seconds,
                     int max_repetitions) noexcept {
  double wanted = 2.0 * repetitions;
  if (elapsed_seconds > 0) {
    wanted = std::max(wanted, std::ceil(1.2 * repetitions * target_seconds / elapsed_seconds));
  } else {
    wanted = 10.0 * repetitions;  // below the clock's resolution: grow fast
  }
  return static_cast<int>(std::min(wanted, static_cast<double>(max_repetitions)));
}

Timing time_runs(const std::function<void()>& run, const TimingPlan& plan) {
  run();  // warm-up: caches, page faults, branch predictors
  const int max_repetitions = std::max(1, plan.max_repetitions);
  int repetitions = 1;
  for (;;) {
    const double elapsed = seconds_for(run, repetitions);
    if (elapsed >= plan.min_sample_seconds || repetitions >= max_repetitions) break;
    repetitions = next_repetitions(repetitions, elapsed, plan.min_sample_seconds, max_repetitions);
  }
  std::vector<double> per_run;
  const int samples = std::max(1, plan.samples);
  for (int i = 0; i < samples; ++i) per_run.push_back(seconds_for(run, repetitions) / repetitions);
  return {spread_of(std::move(per_run)), repetitions, samples};
}
// [/listing]

// [listing time_canvas_fill]
Timing time_canvas_fill(Canvas& canvas, int threads, const TimingPlan& plan) {
  std::uint8_t shade = 0;
  const auto next_color = [&shade] {
    ++shade;
    return Color{shade, static_cast<std::uint8_t>(255 - shade), 128, 255};
  };
  if (threads <= 1) return time_runs([&] { canvas.clear(next_color()); }, plan);
  const int bands = std::min(threads, canvas.height());
  return time_runs(
      [&] {
        const Color color = next_color();
        std::vector<std::jthread> workers;
        workers.reserve(static_cast<std::size_t>(bands));
        for (int band = 0; band < bands; ++band) {
          const int first = canvas.height() * band / bands;
          const int end = canvas.height() * (band + 1) / bands;
          workers.emplace_back(
              [&canvas, first, end, color] { fill_rows(canvas, first, end, color); });
        }
      },
      plan);
}
// [/listing]

double mpix_per_second(double pixels, double seconds) noexcept {
  return seconds > 0 ? pixels / seconds / 1e6 : 0.0;
}

}  // namespace tri::ch09
