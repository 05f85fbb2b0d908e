#pragma once
/// @file
/// The Markdown the listings tool reads: its marker comments, and which lines are code (fenced
/// blocks), not markers. One place, so the listing, measured-number and unmarked-number checks
/// read the same syntax.

#include <string_view>

namespace tri::listings {

inline constexpr std::string_view kFence = "```";
inline constexpr std::string_view kCommentEnd = "-->";
inline constexpr std::string_view kListingOpen = "<!-- listing:";
inline constexpr std::string_view kMeasuredOpen = "<!-- measured:";
inline constexpr std::string_view kMeasuredClose = "<!-- /measured -->";
inline constexpr std::string_view kMeasuredTableOpen = "<!-- measured-table:";
inline constexpr std::string_view kMeasuredTableClose = "<!-- /measured-table -->";

/// The line from its first character that is not a space or a tab.
inline std::string_view trimmed_start(std::string_view line) {
  const auto first = line.find_first_not_of(" \t");
  return first == std::string_view::npos ? std::string_view() : line.substr(first);
}

/// Follows a file's fenced blocks line by line: a marker inside one is an example, not a marker.
class FencedBlocks {
 public:
  /// True for a fence line and for every line inside a fenced block; `line` starts at its
  /// first non-blank character.
  bool is_code(std::string_view line) {
    if (line.starts_with(kFence)) {
      inside_ = !inside_;
      return true;
    }
    return inside_;
  }

 private:
  bool inside_ = false;
};

}  // namespace tri::listings
