#pragma once
/// @file
/// Measured numbers in the Markdown, filled from committed measurement snapshots.
///
/// A marker `<!-- measured: FILE KEY [FORMAT] -->VALUE<!-- /measured -->` sits on one line of a
/// Markdown file (outside fenced blocks and inline code). FILE is a snapshot, relative to the
/// repository root; KEY is one of its keys, `ratio:KEY_A/KEY_B` for the quotient of two, or
/// `header:NAME` for the text of its header line `# NAME: TEXT`. FORMAT is `sN` (N significant
/// digits, more when the number has more digits left of the point) or `fN` (N decimals),
/// optionally followed by a suffix such as `×` or `%`; without FORMAT a number shows three
/// significant digits. Numbers are written as the report writes them (measure/number_format.hpp):
/// trailing zeros are dropped. A text key or a header shows its text as it is, without FORMAT.
///
/// A table comes from a snapshot as a block: a line `<!-- measured-table: FILE TABLE -->`, the
/// table's lines, and a line `<!-- /measured-table -->`. The tool writes every line between the
/// two. TABLE `summary` is the report's table of speed against error, one row per algorithm in the
/// snapshot's order, its cells written as the report's Markdown writes them.
///
/// A snapshot is a text file: lines starting with '#' are its header (machine, compiler, commit,
/// date, peers, note), then the line `key,value`, then one `KEY,VALUE` line per measured number
/// or text.

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "measure/snapshot_reading.hpp"
#include "tools/listings/listings.hpp"

namespace tri::listings {

/// The lines of table `name` of a snapshot (see above), or nullopt with `missing` saying why.
std::optional<std::vector<std::string>> measured_table(const Snapshot& snapshot,
                                                       std::string_view name, std::string& missing);

/// `value` as FORMAT asks (see above), or nullopt when FORMAT is malformed.
std::optional<std::string> format_measured(double value, std::string_view format);

/// Reads each snapshot once; `root` is the repository root that markers' files are relative to.
class SnapshotCache {
 public:
  explicit SnapshotCache(std::filesystem::path root) : root_(std::move(root)) {}
  /// The snapshot, or nullptr when the file is missing or not a snapshot.
  const Snapshot* find(const std::string& file);

 private:
  std::filesystem::path root_;
  std::map<std::string, std::optional<Snapshot>> files_;
};

/// Every marker and table block of one Markdown file's lines checked against its snapshot and
/// rewritten in place from it; returns the markers and blocks read. Values that differ are
/// refreshable problems; a missing snapshot or key and a malformed marker are not, and their values
/// stay as they are.
int fill_measured(const std::string& name, std::vector<std::string>& lines,
                  SnapshotCache& snapshots, std::vector<Problem>& problems);

}  // namespace tri::listings
