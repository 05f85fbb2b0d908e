/// @file
/// How a fuzz check reports the pixels that broke one property: how many, and the first few.
#pragma once

#include <sstream>
#include <string>
#include <vector>

namespace tri::fuzz {

/// Collects pixels that fail one property: a count and the first few positions.
class PixelTally {
 public:
  /// How many example pixels a finding lists; the count says how many there are in all.
  static constexpr int max_examples = 4;

  void add(int x, int y) {
    if (count_ < max_examples) examples_ << " (" << x << ", " << y << ")";
    ++count_;
  }
  int count() const noexcept { return count_; }
  /// "N: (x, y) ..." or "N, e.g. (x, y) ..." when there are more than the examples.
  std::string text() const {
    return std::to_string(count_) + (count_ > max_examples ? ", e.g." : ":") + examples_.str();
  }

 private:
  int count_ = 0;
  std::ostringstream examples_;
};

/// Adds the finding "what N: (x, y) ..." when the tally holds any pixel.
inline void report_pixels(std::vector<std::string>& findings, const std::string& what,
                          const PixelTally& pixels) {
  if (pixels.count() != 0) findings.push_back(what + " " + pixels.text());
}

}  // namespace tri::fuzz
