/// @file
/// Why each optional peer library was not built (CMake's reason), or nullptr when it was, and the
/// report's line about each. Only for the chapter's own library, which CMake gives the
/// TUTORIAL_*_SKIPPED_BECAUSE definitions.
#pragma once

#include <span>
#include <string>
#include <string_view>

namespace tri {

inline constexpr const char* llvmpipe_not_built = TUTORIAL_LLVMPIPE_SKIPPED_BECAUSE;
inline constexpr const char* pixman_not_built = TUTORIAL_PIXMAN_SKIPPED_BECAUSE;
inline constexpr const char* cairo_not_built = TUTORIAL_CAIRO_SKIPPED_BECAUSE;
inline constexpr const char* agg_not_built = TUTORIAL_AGG_SKIPPED_BECAUSE;

/// One library's part of a status line, under `label`: "pixman: measured (pixman_a1)" (just
/// "measured" when the one peer measured is named like the label), "... built, not selected by
/// --only", or "... not built (reason)". The peers measured are those of `measured` that come
/// from `library` (their declared library, never their name).
template <class Peer>
std::string library_status(const std::string& label, const char* not_built,
                           std::string_view library, std::span<const Peer> measured) {
  if (not_built != nullptr) return label + ": not built (" + not_built + ")";
  std::string names;
  for (const Peer& peer : measured) {
    if (peer.library == library) (names += names.empty() ? "" : ", ") += peer.name;
  }
  if (names.empty()) return label + ": built, not selected by --only";
  return label + (names == label ? ": measured" : ": measured (" + names + ")");
}

}  // namespace tri
