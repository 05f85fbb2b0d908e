// The chapter's deterministic figures: the timing plan read off a scripted clock (Step 2) and the
// two speeds read from a snapshot (Step 3).
#include <algorithm>
#include <cmath>
#include <string>

#include <catch2/catch.hpp>

#include "chapters/10_speed_vs_error/suites.hpp"
#include "chapters/10_speed_vs_error/timing_figure.hpp"
#include "chapters/10_speed_vs_error/two_speeds_figure.hpp"
#include "measure/snapshot_reading.hpp"
#include "tests/support/text.hpp"

using tri::ch10::TimedBatch;
using tri::testing::occurrences;
using Stage = tri::ch10::TimedBatch::Stage;

namespace {

// A snapshot of two algorithms whose large scenes' ceilings are 2000 and 1800 Mpix/s.
constexpr const char* small_snapshot =
    "# Measurement snapshot of chapter 10's report, quick setting\n"
    "# machine: Test CPU, 4 hardware threads\n"
    "# compiler: GCC 99 (Release)\n"
    "# commit: abc123\n"
    "# date: 2030-01-02\n"
    "key,value\n"
    "fast_hybrid.large_mpix_per_s,900\n"
    "fast_hybrid.tiny_tris_per_s,3e+06\n"
    "edge_function.large_mpix_per_s,9.5\n"
    "edge_function.tiny_tris_per_s,1.5e+06\n"
    "edge_function.large_integer.mpix_per_s,10\n"
    "edge_function.large_integer.ratio_to_ceiling,0.005\n"
    "edge_function.large_1_256.mpix_per_s,9\n"
    "edge_function.large_1_256.ratio_to_ceiling,0.005\n";

}  // namespace

TEST_CASE("trace_timing reads the warm-up, each calibration batch and the samples off the clock",
          "[10_speed_vs_error][step2]") {
  // Every draw 1.5 ms, batches of 10 ms: 1 draw is short, 1.2 * 10 / 1.5 = 8 draws are enough.
  const tri::TimingPlan plan{0.01, 3, 1000};
  const auto trace = tri::ch10::trace_timing(plan, [](int, double) { return 0.0015; });
  REQUIRE(trace.batches.size() == 1 + 2 + 3);
  CHECK(trace.batches[0].stage == Stage::warm_up);
  CHECK(trace.batches[1].stage == Stage::calibration);
  CHECK(trace.batches[2].stage == Stage::calibration);
  const std::vector<int> draws{1, 1, 8, 8, 8, 8};
  for (std::size_t i = 0; i < draws.size(); ++i) {
    CHECK(trace.batches[i].draws == draws[i]);
    CHECK(trace.batches[i].seconds == Approx(0.0015 * draws[i]).epsilon(1e-9));
    if (i >= 3) CHECK(trace.batches[i].stage == Stage::sample);
  }
  CHECK(trace.timing.repetitions == 8);
  CHECK(trace.timing.seconds.median == Approx(0.0015).epsilon(1e-9));
}

TEST_CASE("The timing figure runs the quick plan to the target and marks the median sample",
          "[10_speed_vs_error][step2]") {
  const tri::TimingPlan plan = tri::ch10::bench_settings(tri::ch10::SuiteSize::quick).timing;
  const auto trace = tri::ch10::trace_timing(plan, tri::ch10::settling_draw_seconds);
  std::vector<TimedBatch> calibration, samples;
  for (const TimedBatch& b : trace.batches) {
    if (b.stage == Stage::calibration) calibration.push_back(b);
    if (b.stage == Stage::sample) samples.push_back(b);
  }
  // The script makes the calibration take more than one step, each as next_repetitions asks,
  // and only the last batch lasts the target.
  REQUIRE(calibration.size() >= 3);
  CHECK(calibration.front().draws == 1);
  for (std::size_t i = 0; i + 1 < calibration.size(); ++i) {
    CHECK(calibration[i].seconds < plan.min_sample_seconds);
    CHECK(calibration[i + 1].draws ==
          tri::next_repetitions(calibration[i].draws, calibration[i].seconds,
                                plan.min_sample_seconds, plan.max_repetitions));
  }
  CHECK(calibration.back().seconds >= plan.min_sample_seconds);
  REQUIRE(samples.size() == static_cast<std::size_t>(plan.samples));
  // One sample waited for another process; the median is one of the others.
  std::vector<double> per_draw;
  for (const TimedBatch& b : samples) per_draw.push_back(b.seconds / b.draws);
  std::sort(per_draw.begin(), per_draw.end());
  CHECK(per_draw.back() > 1.2 * per_draw.front());
  CHECK(trace.timing.seconds.median == per_draw[per_draw.size() / 2]);

  const tri::SvgFigure figure = tri::ch10::timing_plan_figure();
  CHECK(figure.name == "10_timing_plan");
  CHECK(occurrences(figure.svg, "<rect ") == 1 + trace.batches.size() + 4);
  CHECK(occurrences(figure.svg, "stroke=\"#d55e00\" stroke-width=\"3\"") == 1);
  CHECK(occurrences(figure.svg, ">median<") == 1);
  CHECK(occurrences(figure.svg, ">÷" + std::to_string(trace.timing.repetitions) + " = ") == 3);
  CHECK(figure.svg.find("a batch must last 10 ms") != std::string::npos);
}

TEST_CASE("two_speeds_of takes each algorithm's two speeds and the large scenes' mean ceiling",
          "[10_speed_vs_error][step3]") {
  const auto speeds = tri::ch10::two_speeds_of(tri::parse_snapshot(small_snapshot));
  REQUIRE(speeds.rows.size() == 2);
  CHECK(speeds.rows[0].algorithm == "edge_function");  // the figure's order, not the snapshot's
  CHECK(speeds.rows[0].large_mpix_per_s == 9.5);
  CHECK(speeds.rows[0].tiny_tris_per_s == 1.5e6);
  CHECK(speeds.rows[1].algorithm == "fast_hybrid");
  CHECK(speeds.rows[1].large_mpix_per_s == 900);
  // 10 / 0.005 = 2000 and 9 / 0.005 = 1800 Mpix/s: their geometric mean.
  CHECK(speeds.ceiling_mpix_per_s == Approx(std::sqrt(2000.0 * 1800.0)));
  CHECK_THROWS(tri::ch10::two_speeds_of(tri::parse_snapshot("key,value\n")));
}

TEST_CASE("The two-speeds figure draws a bar per speed and names the snapshot's machine and date",
          "[10_speed_vs_error][step3]") {
  const tri::SvgFigure figure = tri::ch10::two_speeds_figure(tri::parse_snapshot(small_snapshot));
  CHECK(figure.name == "10_two_speeds");
  CHECK(figure.svg.find("Measured on Test CPU, 4 hardware threads · GCC 99 (Release) · "
                        "2030-01-02 · commit abc123") != std::string::npos);
  CHECK(figure.svg.find(">write ceiling 1897 Mpix/s<") != std::string::npos);
  CHECK(figure.svg.find(">47.4%<") != std::string::npos);  // 900 / 1897
  CHECK(figure.svg.find(">0.50%<") != std::string::npos);  // 9.5 / 1897
  CHECK(occurrences(figure.svg, "fill=\"#0072b2\"/>") == 2);
  CHECK(occurrences(figure.svg, "fill=\"#e69f00\"/>") == 2);
}
