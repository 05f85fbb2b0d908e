/// @file
/// A small command-line helper, so every executable answers --help and reports bad arguments the
/// same way.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace tri {

/// One option: "--name VALUE" when value_name is not empty, else the flag "--name".
struct CliOption {
  std::string name;
  std::string value_name;
  std::string help;
};

/// The exit statuses of every program, stated at the end of every --help.
inline constexpr int exit_success = 0;
inline constexpr int exit_failure = 1;  ///< unreadable input, failed output, any runtime error
inline constexpr int exit_usage = 2;    ///< a bad command line: nothing was done
inline constexpr const char* exit_status_help =
    "Exit status: 0 success, 1 input, output or runtime error, 2 usage error (nothing done).";

/// A bad command line; what() says what is wrong in one line.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The options a command line gave.
class CliArguments {
 public:
  bool help_requested() const noexcept { return help_; }
  bool has(std::string_view name) const { return values_.contains(std::string(name)); }
  std::optional<std::string> value(std::string_view name) const;
  /// The value of an option, or fallback when it was not given.
  std::string value_or(std::string_view name, std::string_view fallback) const;
  /// The value of an option as a whole number in [low, high]; throws UsageError otherwise.
  std::optional<long long> integer(std::string_view name, long long low, long long high) const;

 private:
  friend class CommandLine;
  bool help_ = false;
  std::map<std::string, std::string, std::less<>> values_;
};

/// Describes a program's options and parses argv against them. --help is always accepted.
class CommandLine {
 public:
  CommandLine(std::string program, std::string summary, std::vector<CliOption> options);

  /// Throws UsageError on an unknown option, an option given twice, a missing or empty value (the
  /// end of the line, or a next word that starts with "--") or a stray argument.
  CliArguments parse(int argc, const char* const* argv) const;
  /// The text --help prints: what the program does, every option and the exit statuses.
  std::string help_text() const;
  const std::string& program() const noexcept { return program_; }

 private:
  const CliOption* find(std::string_view name) const;

  std::string program_;
  std::string summary_;
  std::vector<CliOption> options_;
};

/// The names joined with ", ", as help texts and errors list the valid choices.
std::string comma_separated(const std::vector<std::string>& names);

/// The names of a comma-separated list given to --option: each must be one of valid, none empty
/// (so a leading, trailing or doubled comma is refused) and none twice. Throws UsageError naming
/// the valid names otherwise.
std::vector<std::string> parse_name_list(std::string_view option, std::string_view list,
                                         const std::vector<std::string>& valid);

/// Flushes out (standard output) and checks it: when the results of a successful run could not be
/// written, says so on err with the system's reason and returns exit_failure; a failed run has
/// said why already and keeps its status without a second line.
int finish_standard_output(std::string_view program, std::ostream& out, std::ostream& err,
                           int status);

/// Runs a program body with uniform error handling: prints help and returns 0 for --help, and
/// turns exceptions into one line on err ("program: error: ...", the message escaped by
/// printable_text, so paths and words of the command line cannot break the line or drive the
/// terminal) with exit status 2 for usage errors and 1 for everything else. Checks out at the end
/// (finish_standard_output).
int run_command_line(const CommandLine& command_line, int argc, const char* const* argv,
                     std::ostream& out, std::ostream& err,
                     const std::function<int(const CliArguments&)>& body);

}  // namespace tri
