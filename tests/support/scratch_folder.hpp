/// @file
/// A fresh, empty folder for one test, so that no test writes into the current directory or the
/// source tree.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "common/temporary_folder.hpp"

namespace tri::testing {

/// A TemporaryFolder named after the test (`tri_NAME_XXXXXX`), removed with everything in it when
/// the object goes.
class ScratchFolder : public TemporaryFolder {
 public:
  /// `name` only helps a reader find the folder: letters, digits and '_' are kept as given.
  explicit ScratchFolder(const std::string& name = "test");
};

/// The bytes of a file as a string (empty when it cannot be read).
inline std::string read_text(const std::filesystem::path& path) {
  return whole_file(path);
}

/// Writes text to a file as it is, replacing it.
void write_text(const std::filesystem::path& path, std::string_view text);

/// The names in a folder, sorted, hidden ones included: a leftover temporary shows up.
std::vector<std::string> names_in(const std::filesystem::path& folder);

/// Whether the folder's file system gives unnamed temporary files (Linux O_TMPFILE).
bool has_unnamed_temporaries(const std::filesystem::path& folder);

}  // namespace tri::testing
