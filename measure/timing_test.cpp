// No test here reads a real clock's value: the timing code is checked by what it runs and fills,
// and by what it makes of durations a scripted clock gives it.
#include <algorithm>
#include <chrono>
#include <functional>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "measure/timing.hpp"

using tri::next_repetitions;
using tri::Timing;
using tri::TimingPlan;

TEST_CASE("Calibration aims past the target, at least doubles, and stops at the cap",
          "[measure][timing]") {
  // 1 run took 1 ms, the target is 10 ms: 1.2 * 10 = 12 runs.
  CHECK(next_repetitions(1, 0.001, 0.01, 1000) == 12);
  // Nearly there: still at least double.
  CHECK(next_repetitions(10, 0.009, 0.01, 1000) == 20);
  // Below the clock's resolution: ten times more.
  CHECK(next_repetitions(3, 0.0, 0.01, 1000) == 30);
  CHECK(next_repetitions(600, 0.001, 0.01, 1000) == 1000);
}

TEST_CASE("A zero target times one warm-up, one calibration and the samples, one run each",
          "[measure][timing]") {
  int runs = 0;
  const Timing timing = tri::time_runs([&] { ++runs; }, TimingPlan{0.0, 3, 100});
  CHECK(runs == 1 + 1 + 3);
  CHECK(timing.repetitions == 1);
  CHECK(timing.samples == 3);
  CHECK(timing.seconds.min <= timing.seconds.median);
  CHECK(timing.seconds.median <= timing.seconds.max);
}

TEST_CASE("Calibration never runs more than the cap per sample", "[measure][timing]") {
  int runs = 0;
  // An hour per sample is never reached: the first guess jumps to the cap of 8, which ends the
  // calibration.
  const Timing timing = tri::time_runs([&] { ++runs; }, TimingPlan{3600.0, 2, 8});
  CHECK(timing.repetitions == 8);
  CHECK(timing.samples == 2);
  CHECK(runs == 1 + (1 + 8) + 2 * 8);
}

TEST_CASE("Fixed repetitions skip the calibration and run that often per sample",
          "[measure][timing]") {
  int runs = 0;
  TimingPlan plan{3600.0, 4, 1000};
  plan.repetitions = 3;
  const Timing timing = tri::time_runs([&] { ++runs; }, plan);
  CHECK(timing.repetitions == 3);
  CHECK(runs == 1 + 4 * 3);
}

TEST_CASE("Interleaved timing warms up and calibrates each run, then samples them in turn",
          "[measure][timing]") {
  std::string calls;
  const std::vector<std::function<void()>> runs{[&] { calls += 'a'; }, [&] { calls += 'b'; }};
  std::vector<int> rounds_heard;
  const std::vector<Timing> timings = tri::time_interleaved(
      runs, TimingPlan{0.0, 3, 100}, [&](int done) { rounds_heard.push_back(done); });
  // Warm-up and one calibration run of a, then of b, then three rounds of a and b.
  CHECK(calls == "aabbababab");
  CHECK(rounds_heard == std::vector<int>{1, 2, 3});
  REQUIRE(timings.size() == 2);
  for (const Timing& timing : timings) {
    CHECK(timing.samples == 3);
    CHECK(timing.seconds.min <= timing.seconds.median);
    CHECK(timing.seconds.median <= timing.seconds.max);
  }
}

TEST_CASE(
    "On a scripted clock, calibration reaches the target and the median ignores one slow sample",
    "[measure][timing]") {
  using namespace std::chrono_literals;
  std::chrono::steady_clock::time_point now{};
  int runs = 0;
  // Every run takes 1.5 ms, except the eight of the second sample (runs 18 to 25): 3 ms each.
  const auto run = [&] {
    now += runs >= 18 && runs < 26 ? 3000us : 1500us;
    ++runs;
  };
  const Timing timing = tri::time_runs(run, TimingPlan{0.01, 3, 1000}, [&] { return now; });
  // Warm-up, then 1 run (1.5 ms, short of 10 ms): 1.2 * 10 / 1.5 = 8 runs, 12 ms, enough.
  CHECK(timing.repetitions == 8);
  CHECK(runs == 1 + (1 + 8) + 3 * 8);
  CHECK(timing.seconds.median == Approx(0.0015).epsilon(1e-12));
  CHECK(timing.seconds.min == Approx(0.0015).epsilon(1e-12));
  CHECK(timing.seconds.max == Approx(0.003).epsilon(1e-12));
}

TEST_CASE("Mpixels per second divide pixels by seconds, and no time gives 0", "[measure][timing]") {
  CHECK(tri::mpix_per_second(2e6, 0.5) == 4.0);
  CHECK(tri::mpix_per_second(2e6, 0.0) == 0.0);
}
