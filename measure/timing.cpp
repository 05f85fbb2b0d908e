#include "measure/timing.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace tri {
namespace {

// Wall time on steady_clock: the one clock that also times threaded variants and external peers;
// a shared machine's noise is met by interleaved rounds and the median instead.
using Clock = std::chrono::steady_clock;

}  // namespace

Clock::time_point steady_now() noexcept {
  return Clock::now();
}

double seconds_of(const std::function<void()>& run, int repetitions, const TimingClock& clock) {
  const auto start = clock();
  for (int i = 0; i < repetitions; ++i) run();
  return std::chrono::duration<double>(clock() - start).count();
}

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

namespace {

int calibrated_repetitions(const std::function<void()>& run, const TimingPlan& plan,
                           const TimingClock& clock) {
  run();  // warm-up: caches, page faults, branch predictors
  if (plan.repetitions > 0) return plan.repetitions;
  const int max_repetitions = std::max(1, plan.max_repetitions);
  int repetitions = 1;
  for (;;) {
    const double elapsed = seconds_of(run, repetitions, clock);
    if (elapsed >= plan.min_sample_seconds || repetitions >= max_repetitions) return repetitions;
    repetitions = next_repetitions(repetitions, elapsed, plan.min_sample_seconds, max_repetitions);
  }
}

}  // namespace

// [listing interleaved_rounds]
std::vector<Timing> time_interleaved(std::span<const std::function<void()>> runs,
                                     const TimingPlan& plan,
                                     const std::function<void(int rounds_done)>& after_round,
                                     const TimingClock& clock) {
  std::vector<int> repetitions;
  for (const auto& run : runs) repetitions.push_back(calibrated_repetitions(run, plan, clock));
  const int samples = std::max(1, plan.samples);
  std::vector<std::vector<double>> per_run(runs.size());
  for (int round = 0; round < samples; ++round) {
    for (std::size_t i = 0; i < runs.size(); ++i) {
      per_run[i].push_back(seconds_of(runs[i], repetitions[i], clock) / repetitions[i]);
    }
    if (after_round) after_round(round + 1);
  }
  std::vector<Timing> timings;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    timings.push_back({spread_of(std::move(per_run[i])), repetitions[i], samples});
  }
  return timings;
}
// [/listing]

Timing time_runs(const std::function<void()>& run, const TimingPlan& plan,
                 const TimingClock& clock) {
  return time_interleaved(std::span(&run, 1), plan, {}, clock).front();
}

double mpix_per_second(double pixels, double seconds) noexcept {
  return seconds > 0 ? pixels / seconds / 1e6 : 0.0;
}

}  // namespace tri
