/// @file
/// Why each optional peer library was not built (CMake's reason), or nullptr when it was, and the
/// report's line about each. Only for the chapter's own library, which CMake gives the
/// TUTORIAL_*_SKIPPED_BECAUSE definitions.
#pragma once

#include <span>
#include <string>

namespace tri {

inline constexpr const char* llvmpipe_not_built = TUTORIAL_LLVMPIPE_SKIPPED_BECAUSE;
inline constexpr const char* pixman_not_built = TUTORIAL_PIXMAN_SKIPPED_BECAUSE;
inline constexpr const char* cairo_not_built = TUTORIAL_CAIRO_SKIPPED_BECAUSE;
inline constexpr const char* agg_not_built = TUTORIAL_AGG_SKIPPED_BECAUSE;

/// One library's part of a status line: "pixman: measured (pixman_a1)" (just "measured" when
/// the one peer measured is named like the library), "... built, not selected by --only", or
/// "... not built (reason)". The peers measured are those of `measured` whose name starts with
/// `name_prefix`.
template <class Peer>
std::string library_status(const std::string& library, const char* not_built,
                           const std::string& name_prefix, std::span<const Peer> measured) {
  if (not_built != nullptr) return library + ": not built (" + not_built + ")";
  std::string names;
  for (const Peer& peer : measured) {
    if (peer.name.starts_with(name_prefix)) names += (names.empty() ? "" : ", ") + peer.name;
  }
  if (names.empty()) return library + ": built, not selected by --only";
  return library + (names == library ? ": measured" : ": measured (" + names + ")");
}

}  // namespace tri
