/// @file
/// Reading a measurement snapshot back (the format snapshot.hpp writes): its header lines and its
/// numbers by key, for the figures drawn from a committed snapshot.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>

namespace tri::ch10 {

/// One snapshot as written: `# name: text` header lines, then `key,value`, then KEY,VALUE lines.
struct SnapshotValues {
  std::map<std::string, std::string, std::less<>> header;  ///< "machine", "date", ... to their text
  std::map<std::string, double, std::less<>> numbers;

  /// The header's text for `name`, or "unknown".
  std::string header_text(std::string_view name) const;
  /// The number under `key`, or nullopt when the snapshot has none.
  std::optional<double> number(std::string_view key) const;
};

/// The snapshot in `text`; throws std::runtime_error naming the first line that is not one.
SnapshotValues parse_snapshot_values(std::string_view text);

/// The snapshot in a file; throws std::runtime_error when it cannot be read or parsed.
SnapshotValues read_snapshot_values(const std::filesystem::path& file);

}  // namespace tri::ch10
