/// @file
/// Running another program (no shell) and reading what it printed, in a private temporary
/// folder: how the report times `raster` as a user runs it, and how chapter 11 grades a program
/// given by --command, with a deadline.
#pragma once

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "common/temporary_folder.hpp"

namespace tri {

/// How a program ran: what it printed, and how it ended.
struct ProgramRun {
  std::string output;      ///< its standard output (empty when discarded)
  std::string errors;      ///< its standard error
  int exit_code = -1;      ///< its exit status, or -1 when a signal ended it
  int signal = 0;          ///< the signal that ended it, or 0
  bool timed_out = false;  ///< it ran past the deadline and was killed (SIGKILL)

  bool succeeded() const noexcept { return exit_code == 0; }
};

/// How run_program starts a program and how long it waits for it.
struct ProgramOptions {
  /// A words[0] without '/' is looked up in PATH (posix_spawnp); otherwise it is a path.
  bool search_path = false;
  /// Its standard output goes to /dev/null instead of into ProgramRun::output.
  bool discard_output = false;
  /// Past this moment the program is killed (not the processes it started itself); none: waits.
  std::optional<std::chrono::steady_clock::time_point> deadline;
};

/// Runs words[0] with the other words as its arguments, no standard input, in this process's
/// group (an interrupt from the terminal ends it too), and waits for it to end. Throws
/// std::runtime_error with the system's reason when it cannot be started (a missing file, a file
/// that is not a program) or waited for.
ProgramRun run_program(const std::vector<std::string>& words, const ProgramOptions& options = {});

}  // namespace tri
