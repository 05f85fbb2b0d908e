/// @file
/// Running another program of the build (no shell) and reading what it printed, in a private
/// temporary folder: how the report times `raster` as a user runs it.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace tri {

/// A folder of its own under the system's temporary folder, removed with its contents when the
/// object goes.
class TemporaryFolder {
 public:
  /// Makes the folder; prefix starts its name. Throws std::runtime_error with the system's reason.
  explicit TemporaryFolder(const std::string& prefix);
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;
  ~TemporaryFolder();
  const std::filesystem::path& path() const noexcept { return path_; }

 private:
  std::filesystem::path path_;
};

/// How a program ran: what it printed, and how it ended.
struct ProgramRun {
  std::string output;  ///< its standard output
  std::string errors;  ///< its standard error
  int exit_code = -1;  ///< its exit status, or -1 when a signal ended it
  int signal = 0;      ///< the signal that ended it, or 0

  bool succeeded() const noexcept { return exit_code == 0; }
};

/// Runs words[0] (a path: no shell, PATH not searched) with the other words as its arguments and
/// no standard input, and waits for it to end. Throws std::runtime_error with the system's reason
/// when it cannot be started (a missing file, a file that is not a program).
ProgramRun run_program(const std::vector<std::string>& words);

}  // namespace tri
