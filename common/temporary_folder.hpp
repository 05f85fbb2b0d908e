/// @file
/// A private folder under the system's temporary folder for files a program writes and reads
/// back (a scene handed to another program, what it printed, a test's outputs), and reading a
/// file back whole.
#pragma once

#include <filesystem>
#include <string>

namespace tri {

/// A new folder under the system's temporary folder (TMPDIR when set), made unique by mkdtemp,
/// removed with everything in it when the object goes.
class TemporaryFolder {
 public:
  /// Makes the folder `prefix_XXXXXX`. Throws std::runtime_error with the system's reason.
  explicit TemporaryFolder(const std::string& prefix);
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;
  ~TemporaryFolder();

  const std::filesystem::path& path() const noexcept { return path_; }
  std::filesystem::path operator/(const std::filesystem::path& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

/// The bytes of a file as a string; empty when it cannot be read.
std::string whole_file(const std::filesystem::path& path);

}  // namespace tri
