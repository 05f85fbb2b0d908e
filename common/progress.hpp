/// @file
/// Long work says so: a progress line on standard error once work has run for a while, with an
/// estimate of the time left, and a guard against runs whose estimate is absurd.
#pragma once

#include <chrono>
#include <cstdint>
#include <ostream>
#include <string>

namespace tri {

/// Work that is estimated to take longer than this is refused unless the user insists (--force).
inline constexpr std::chrono::minutes max_unforced_run{10};

/// "12 s", "4 min", "3.2 h": a duration as a person reads it.
std::string human_duration(double seconds);

/// Throws UsageError when estimated_seconds exceeds max_unforced_run and forced is false, saying
/// what would take that long and how to go ahead.
void refuse_absurd_run(double estimated_seconds, const std::string& what, bool forced);

/// Reports the progress of work of known size: nothing for the first quiet period, then one line
/// "label: 42% done, about 12 s left" at most every interval.
class Progress {
 public:
  using Clock = std::chrono::steady_clock;

  Progress(std::string label, std::uint64_t total, std::ostream& err,
           Clock::duration quiet = std::chrono::seconds(2),
           Clock::duration interval = std::chrono::seconds(2));

  /// Says that done of total units are finished (a fraction of a unit counts too); prints a line
  /// when one is due.
  void advance(double done);
  /// How many lines were printed so far.
  int lines_printed() const noexcept { return lines_; }

 private:
  std::string label_;
  std::uint64_t total_;
  std::ostream& err_;
  Clock::time_point start_;
  Clock::time_point next_report_;
  Clock::duration interval_;
  int lines_ = 0;
};

}  // namespace tri
