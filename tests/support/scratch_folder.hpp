/// @file
/// A fresh, empty folder for one test, so that no test writes into the current directory or the
/// source tree.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace tri::testing {

/// A new folder under the system's temporary folder (TMPDIR when set), named after the test and
/// made unique by mkdtemp, removed with everything in it when the object goes.
class ScratchFolder {
 public:
  /// `name` only helps a reader find the folder: letters, digits and '_' are kept as given.
  explicit ScratchFolder(const std::string& name = "test");
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  ~ScratchFolder();

  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::filesystem::path& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

/// The bytes of a file as a string (empty when it cannot be read).
std::string read_text(const std::filesystem::path& path);

/// Writes text to a file as it is, replacing it.
void write_text(const std::filesystem::path& path, std::string_view text);

/// The names in a folder, sorted, hidden ones included: a leftover temporary shows up.
std::vector<std::string> names_in(const std::filesystem::path& folder);

/// Whether the folder's file system gives unnamed temporary files (Linux O_TMPFILE).
bool has_unnamed_temporaries(const std::filesystem::path& folder);

}  // namespace tri::testing
