#pragma once
/// @file
/// Code listings in the chapter READMEs, kept equal to marked regions of the real sources.
///
/// A source file marks a region with a line `// [listing NAME]` before it and a line
/// `// [/listing]` after it (the marker lines are not part of the listing). Regions may not nest
/// or overlap, and a name is used once per file. A README shows a region with an HTML comment
/// naming the file (relative to the repository root) and the region, directly followed by a
/// fenced `cpp` block that holds the region's text, its common indentation removed.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace tri::listings {

/// The command that rewrites every listing from the sources; failure messages name it.
inline constexpr std::string_view kRefreshCommand =
    "cmake --build --preset release --target listings";

/// The command that measures a quick run into its snapshot and refills every measured number.
inline constexpr std::string_view kMeasuredRefreshCommand =
    "cmake --build --preset release --target measured_numbers";

/// One thing wrong, at a line of a file (the path relative to the root, line counted from 1).
struct Problem {
  std::string file;
  int line = 0;
  std::string message;
  bool refreshable = false;  ///< --update fixes it (a listing that differs or lacks its block)
};

/// "file:line: message", the form compilers use, so editors can jump to it.
std::string format(const Problem& problem);

/// One marked region of a source file.
struct Region {
  std::string name;
  int first_line = 0;  ///< the line of its opening marker
  std::string text;    ///< its lines, common indentation removed, each ending in '\n'
};

/// The regions of one source file, and what is wrong with its markers.
struct Markers {
  std::vector<Region> regions;
  std::vector<Problem> problems;
};

/// Reads the markers of one source file's text; `file` only names it in problems.
Markers parse_markers(std::string_view text, const std::string& file);

/// What a run over a repository found.
struct Report {
  int listings = 0;                    ///< listing comments read in the Markdown files
  int measured = 0;                    ///< measured-number markers read (see measured.hpp)
  std::vector<std::string> rewritten;  ///< Markdown files --update changed
  std::vector<Problem> problems;
};

/// Checks that every listing in the Markdown files under `root` equals its marked region, that
/// every listing names an existing file and region, that every source's markers balance, and
/// that every measured number equals its snapshot (see measured.hpp).
Report check_listings(const std::filesystem::path& root);

/// Rewrites every listing from its region (adding the fenced block after a comment that has
/// none) and every measured number from its snapshot. Listings whose file or region is missing,
/// and markers whose snapshot or key is missing, are left as they are and reported.
Report update_listings(const std::filesystem::path& root);

}  // namespace tri::listings
