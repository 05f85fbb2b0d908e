#pragma once
/// @file
/// Measured numbers in the Markdown, filled from committed measurement snapshots.
///
/// A marker `<!-- measured: FILE KEY [FORMAT] -->VALUE<!-- /measured -->` sits on one line of a
/// Markdown file (outside fenced blocks and inline code). FILE is a snapshot, relative to the
/// repository root; KEY is one of its keys, or `ratio:KEY_A/KEY_B` for the quotient of two.
/// FORMAT is `sN` (N significant digits) or `fN` (N decimals), optionally followed by a suffix
/// such as `×` or `%`; without FORMAT a number shows three significant digits.
///
/// A snapshot is a text file: lines starting with '#' are its header (machine, compiler, commit,
/// date), then the line `key,value`, then one `KEY,VALUE` line per measured number.

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tools/listings/listings.hpp"

namespace tri::listings {

/// The numbers of one snapshot by key; nullopt when the text is not a snapshot.
std::optional<std::map<std::string, double, std::less<>>> parse_snapshot(std::string_view text);

/// `value` as FORMAT asks (see above), or nullopt when FORMAT is malformed.
std::optional<std::string> format_measured(double value, std::string_view format);

/// Reads each snapshot once; `root` is the repository root that markers' files are relative to.
class SnapshotCache {
 public:
  explicit SnapshotCache(std::filesystem::path root) : root_(std::move(root)) {}
  /// The snapshot's numbers, or nullptr when the file is missing or not a snapshot.
  const std::map<std::string, double, std::less<>>* find(const std::string& file);

 private:
  std::filesystem::path root_;
  std::map<std::string, std::optional<std::map<std::string, double, std::less<>>>> files_;
};

/// Every marker of one Markdown file's lines checked against its snapshot and rewritten in
/// place from it; returns the markers read. Values that differ are refreshable problems; a
/// missing snapshot or key and a malformed marker are not, and their values stay as they are.
int fill_measured(const std::string& name, std::vector<std::string>& lines,
                  SnapshotCache& snapshots, std::vector<Problem>& problems);

}  // namespace tri::listings
