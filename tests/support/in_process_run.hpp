/// @file
/// A program's entry point run in the test's own process, its output captured, so that a test
/// checks what a command line prints and returns without starting a process.
#pragma once

#include <functional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace tri::testing {

/// What one run printed and returned.
struct InProcessRun {
  int status = 0;
  std::string out;
  std::string err;
};

/// A program's entry point as the apps offer it: main's arguments and the two streams.
using ProgramEntry = std::function<int(int, const char* const*, std::ostream&, std::ostream&)>;

/// Runs `entry` as `program args...` would run from a shell (argv[0] is `program`).
InProcessRun run_in_process(std::string_view program, const std::vector<std::string>& args,
                            const ProgramEntry& entry);

}  // namespace tri::testing
