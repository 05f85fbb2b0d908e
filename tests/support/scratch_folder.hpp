/// @file
/// A fresh, empty folder for one test, so that no test writes into the current directory or the
/// source tree.
#pragma once

#include <filesystem>
#include <string>

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

}  // namespace tri::testing
