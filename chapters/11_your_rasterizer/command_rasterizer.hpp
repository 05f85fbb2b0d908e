/// @file
/// A rasterizer graded through --command: any program that reads a scene file and writes its
/// write counts as a binary PGM (as `raster --counts` does), run once per case without a shell.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "chapters/11_your_rasterizer/graded_rasterizer.hpp"

namespace tri::conformance {

/// The words of a command line, split at spaces and tabs; single or double quotes keep spaces in
/// a word (no other shell syntax: no variables, globs, pipes or escapes). Throws UsageError for
/// an unclosed quote, an empty command, or one without both {scene} and {counts}.
std::vector<std::string> command_words(std::string_view command);

/// The program the words name, started for each case with posix_spawnp (no shell, PATH searched):
/// {scene} in any word is replaced by the path of the case's scene file, {counts} by the path the
/// counts must be written to, both new for each run in a private temporary folder. Its standard
/// input is /dev/null, its standard output discarded, its standard error kept for the reason. A
/// run past the deadline is killed (SIGKILL; not the processes it started itself) and fails;
/// death by a signal fails; a non-zero exit with a message is a refusal, without one a failure;
/// an unreadable or missing counts file fails.
GradedRasterizer graded_command(std::string_view command);

}  // namespace tri::conformance
