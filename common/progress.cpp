#include "common/progress.hpp"

#include <cmath>
#include <sstream>

#include "common/cli.hpp"

namespace tri {

std::string human_duration(double seconds) {
  std::ostringstream text;
  text.precision(2);
  if (seconds < 90) {
    text << std::lround(seconds) << " s";
  } else if (seconds < 90 * 60) {
    text << std::lround(seconds / 60) << " min";
  } else {
    text << std::fixed;
    text.precision(1);
    text << seconds / 3600 << " h";
  }
  return text.str();
}

void refuse_absurd_run(double estimated_seconds, const std::string& what, bool forced) {
  const double limit = std::chrono::duration<double>(max_unforced_run).count();
  if (forced || estimated_seconds <= limit) return;
  throw UsageError(what + " would take about " + human_duration(estimated_seconds) +
                   ", more than " + human_duration(limit) + "; add --force to run it anyway");
}

Progress::Progress(std::string label, std::uint64_t total, std::ostream& err, Clock::duration quiet,
                   Clock::duration interval)
    : label_(std::move(label)),
      total_(total),
      err_(err),
      start_(Clock::now()),
      next_report_(start_ + quiet),
      interval_(interval) {}

void Progress::advance(double done) {
  const auto now = Clock::now();
  const auto total = static_cast<double>(total_);
  if (now < next_report_ || total_ == 0 || done <= 0 || done >= total) return;
  next_report_ = now + interval_;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double fraction = done / total;
  const double left = elapsed / fraction - elapsed;
  err_ << label_ << ": " << std::lround(100 * fraction) << "% done, about " << human_duration(left)
       << " left\n";
  err_.flush();
  ++lines_;
}

}  // namespace tri
