/// @file
/// Why each optional peer library was not built (CMake's reason), or nullptr when it was, and the
/// report's line about each. Only for the peers library, which CMake gives the
/// TUTORIAL_*_SKIPPED_BECAUSE definitions.
#pragma once

#include <initializer_list>
#include <span>
#include <string>
#include <string_view>

namespace tri {

inline constexpr const char* llvmpipe_not_built = TUTORIAL_LLVMPIPE_SKIPPED_BECAUSE;
inline constexpr const char* pixman_not_built = TUTORIAL_PIXMAN_SKIPPED_BECAUSE;
inline constexpr const char* cairo_not_built = TUTORIAL_CAIRO_SKIPPED_BECAUSE;
inline constexpr const char* agg_not_built = TUTORIAL_AGG_SKIPPED_BECAUSE;
inline constexpr const char* freetype_not_built = TUTORIAL_FREETYPE_SKIPPED_BECAUSE;

/// A library the peers come from, as a status line names it: its label there, why it was not
/// built (nullptr when it was), and the library its peers declare.
struct PeerLibrary {
  std::string label;
  const char* not_built;
  std::string_view library;
};

/// The status line of these libraries, one part each, separated by "; ". A part is
/// "pixman: measured (pixman_a1)" (just "measured" when the one peer measured is named like the
/// label), "... built, not selected by --only", or "... not built (reason)". The peers measured
/// are those of `measured` that declare the library (never told by their name).
template <class Peer>
std::string status_line(std::initializer_list<PeerLibrary> libraries,
                        std::span<const Peer> measured) {
  std::string line;
  for (const PeerLibrary& l : libraries) {
    std::string names;
    for (const Peer& peer : measured) {
      if (peer.library == l.library) (names += names.empty() ? "" : ", ") += peer.name;
    }
    (line += line.empty() ? "" : "; ") += l.label;
    if (l.not_built != nullptr) {
      line += std::string(": not built (") + l.not_built + ")";
    } else if (names.empty()) {
      line += ": built, not selected by --only";
    } else {
      line += names == l.label ? ": measured" : ": measured (" + names + ")";
    }
  }
  return line;
}

}  // namespace tri
