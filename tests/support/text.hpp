/// @file
/// Text helpers for tests that read what a program wrote (SVG, Markdown, CSV).
#pragma once

#include <cstddef>
#include <string_view>

namespace tri::testing {

/// How many times `part` occurs in `text`, overlapping occurrences included.
inline std::size_t occurrences(std::string_view text, std::string_view part) {
  std::size_t count = 0;
  for (auto at = text.find(part); at != std::string_view::npos; at = text.find(part, at + 1)) {
    ++count;
  }
  return count;
}

}  // namespace tri::testing
