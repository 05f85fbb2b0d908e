/// @file
/// Reading a measurement snapshot back (the format chapter 10's report writes with --snapshot):
/// its header lines, and its values by key, numbers and texts apart. The figures drawn from a
/// committed snapshot and the Markdown markers that quote it read it here, the one reader.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tri {

/// One snapshot as written: `# NAME: TEXT` header lines, then `key,value`, then KEY,VALUE lines.
struct Snapshot {
  std::map<std::string, std::string, std::less<>> header;  ///< "machine", "date", ... to their text
  std::map<std::string, double, std::less<>> numbers;      ///< the values that are numbers
  std::map<std::string, std::string, std::less<>> texts;   ///< the values that are not
  std::vector<std::string> keys;                           ///< every key, in the file's order

  /// The header's text for `name`, or "unknown".
  std::string header_text(std::string_view name) const;
  /// The number under `key`, or nullopt when the snapshot has no number there.
  std::optional<double> number(std::string_view key) const;
};

/// The snapshot in `text`; throws std::runtime_error naming the first line that is not one.
Snapshot parse_snapshot(std::string_view text);

/// The snapshot in a file; throws std::runtime_error naming the file when it cannot be read or
/// parsed.
Snapshot read_snapshot(const std::filesystem::path& file);

}  // namespace tri
