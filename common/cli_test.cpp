#include <catch2/catch.hpp>

#include <climits>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <optional>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/cli.hpp"

namespace tri {
namespace {

CommandLine raster_like() {
  return CommandLine("raster", "Renders a scene with one triangle algorithm.",
                     {{"algo", "NAME", "the algorithm to use"},
                      {"scene", "FILE", "the scene to render"},
                      {"list", "", "list the algorithms and exit"},
                      {"bench", "N", "draw the scene N times and print the speed"}});
}

// argv as a program receives it: the program name first.
struct Argv {
  explicit Argv(std::initializer_list<const char*> words) : words_{"raster"} {
    words_.insert(words_.end(), words);
  }
  int argc() const { return static_cast<int>(words_.size()); }
  const char* const* argv() const { return words_.data(); }

 private:
  std::vector<const char*> words_;
};

CliArguments parse(std::initializer_list<const char*> words) {
  const Argv args(words);
  return raster_like().parse(args.argc(), args.argv());
}

// The UsageError message for a command line, or a note that there was none.
std::string usage_error_of(std::initializer_list<const char*> words) {
  try {
    parse(words);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "(no UsageError)";
}

struct Outcome {
  int status;
  std::string out;
  std::string err;
  int body_calls;
};

Outcome run(std::initializer_list<const char*> words,
            const std::function<int(const CliArguments&)>& body) {
  const Argv args(words);
  std::ostringstream out;
  std::ostringstream err;
  int calls = 0;
  const int status = run_command_line(raster_like(), args.argc(), args.argv(), out, err,
                                      [&](const CliArguments& parsed) {
                                        ++calls;
                                        return body(parsed);
                                      });
  return {status, out.str(), err.str(), calls};
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// True when one line of the text holds both pieces, in this order.
bool has_line_with(const std::string& text, const std::string& first, const std::string& then) {
  for (const std::string& line : lines_of(text)) {
    const auto at = line.find(first);
    if (at != std::string::npos && line.find(then, at + first.size()) != std::string::npos) {
      return true;
    }
  }
  return false;
}

bool has_line_matching(const std::string& text, const std::string& pattern) {
  const std::regex line_pattern(pattern);
  for (const std::string& line : lines_of(text)) {
    if (std::regex_match(line, line_pattern)) return true;
  }
  return false;
}

}  // namespace

TEST_CASE("An empty command line gives no options", "[common][cli]") {
  const CliArguments args = parse({});
  CHECK_FALSE(args.help_requested());
  CHECK_FALSE(args.has("scene"));
  CHECK_FALSE(args.value("scene").has_value());
  CHECK(args.value_or("scene", "default.scene") == "default.scene");
  CHECK_FALSE(args.integer("bench", 1, 10).has_value());
}

TEST_CASE("--help and -h ask for help", "[common][cli]") {
  CHECK(parse({"--help"}).help_requested());
  CHECK(parse({"-h"}).help_requested());
  CHECK(parse({"--scene", "a.scene", "--help"}).help_requested());
}

TEST_CASE("Options with values and flags are read back by name", "[common][cli]") {
  const CliArguments args = parse({"--scene", "my file.scene", "--list", "--algo", "-x"});
  CHECK_FALSE(args.help_requested());
  CHECK(args.value("scene") == std::optional<std::string>("my file.scene"));
  CHECK(args.value_or("scene", "other") == "my file.scene");
  CHECK(args.has("list"));
  CHECK(args.value("list") == std::optional<std::string>(""));
  CHECK(args.value("algo") == std::optional<std::string>("-x"));  // one dash is a value
  CHECK_FALSE(args.has("bench"));
  CHECK_FALSE(args.has("help"));
}

TEST_CASE("The help text names the program, its summary and every option with its help",
          "[common][cli]") {
  const std::string help = raster_like().help_text();
  CHECK_THAT(help, Catch::StartsWith("Usage: raster [options]\n"));
  CHECK_THAT(help, Catch::Contains("Renders a scene with one triangle algorithm."));
  CHECK(has_line_with(help, "--help, -h", "print this help"));
  CHECK(has_line_with(help, "--algo NAME", "the algorithm to use"));
  CHECK(has_line_with(help, "--scene FILE", "the scene to render"));
  CHECK(has_line_with(help, "--list", "list the algorithms and exit"));
  CHECK(has_line_with(help, "--bench N", "draw the scene N times and print the speed"));
  // A flag shows no value name: only spaces between it and its help.
  CHECK(has_line_matching(help, "  --list +list the algorithms and exit"));
  CHECK(raster_like().program() == "raster");
}

TEST_CASE("A bad command line throws a UsageError that says what is wrong",
          "[common][cli][errors]") {
  CHECK(usage_error_of({"--bogus"}) == "unknown option '--bogus'");
  CHECK(usage_error_of({"--Scene", "a"}) == "unknown option '--Scene'");
  CHECK(usage_error_of({"--scene=a.scene"}) == "unknown option '--scene=a.scene'");
  CHECK(usage_error_of({"--"}) == "unknown option '--'");
  CHECK(usage_error_of({"-x"}) == "unexpected argument '-x'");
  CHECK(usage_error_of({"a.scene"}) == "unexpected argument 'a.scene'");
  CHECK(usage_error_of({"--scene", "a.scene", "b.scene"}) == "unexpected argument 'b.scene'");
  CHECK(usage_error_of({"--scene"}) == "option '--scene' needs a value (FILE)");
  CHECK(usage_error_of({"--list", "--bench"}) == "option '--bench' needs a value (N)");
  CHECK(usage_error_of({"--list", "--list"}) == "option '--list' given twice");
  CHECK(usage_error_of({"--scene", "a", "--scene", "b"}) == "option '--scene' given twice");
  CHECK(usage_error_of({"--scene", ""}) == "option '--scene' needs a non-empty value (FILE)");
}

TEST_CASE("An option does not swallow the next option as its value", "[common][cli][errors]") {
  CHECK(usage_error_of({"--scene", "--list"}) == "option '--scene' needs a value (FILE)");
  CHECK(usage_error_of({"--algo", "--help"}) == "option '--algo' needs a value (NAME)");
}

TEST_CASE("integer reads whole numbers within the bounds and refuses everything else",
          "[common][cli][integer]") {
  CHECK(parse({"--bench", "1"}).integer("bench", 1, 100) == 1);
  CHECK(parse({"--bench", "100"}).integer("bench", 1, 100) == 100);
  CHECK(parse({"--bench", "42"}).integer("bench", 1, 100) == 42);
  CHECK(parse({"--bench", "-7"}).integer("bench", -10, 10) == -7);
  CHECK(parse({"--bench", "9223372036854775807"}).integer("bench", 0, LLONG_MAX) == LLONG_MAX);

  for (const char* bad : {"0", "101", "-1", " 5", "5 ", "+5", "1.5", "1e2", "abc", "10x", "0x10",
                          "99999999999999999999"}) {
    INFO("--bench '" << bad << "'");
    const CliArguments args = parse({"--bench", bad});
    CHECK_THROWS_AS(args.integer("bench", 1, 100), UsageError);
    CHECK_THROWS_WITH(
        args.integer("bench", 1, 100),
        "--bench expects a whole number from 1 to 100, got '" + std::string(bad) + "'");
  }
}

TEST_CASE("run_command_line prints the help on out and returns 0 without running the body",
          "[common][cli][run]") {
  const Outcome outcome = run({"--help"}, [](const CliArguments&) { return 5; });
  CHECK(outcome.status == 0);
  CHECK(outcome.out == raster_like().help_text());
  CHECK(outcome.err.empty());
  CHECK(outcome.body_calls == 0);
}

TEST_CASE("run_command_line returns the body's status and passes it the parsed options",
          "[common][cli][run]") {
  const Outcome outcome = run({"--scene", "a.scene"}, [](const CliArguments& args) {
    return args.value("scene") == std::optional<std::string>("a.scene") ? 7 : 99;
  });
  CHECK(outcome.status == 7);
  CHECK(outcome.out.empty());
  CHECK(outcome.err.empty());
  CHECK(outcome.body_calls == 1);
}

TEST_CASE("run_command_line reports a usage error on err with status 2 and writes nothing on out",
          "[common][cli][run]") {
  const Outcome outcome = run({"--bogus"}, [](const CliArguments&) { return 0; });
  CHECK(outcome.status == 2);
  CHECK(outcome.out.empty());
  CHECK(outcome.err == "raster: error: unknown option '--bogus' (see --help)\n");
  CHECK(outcome.body_calls == 0);
}

TEST_CASE("run_command_line treats a UsageError from the body as a usage error",
          "[common][cli][run]") {
  const Outcome outcome = run({"--bench", "0"}, [](const CliArguments& args) {
    return static_cast<int>(args.integer("bench", 1, 10).value_or(0));
  });
  CHECK(outcome.status == 2);
  CHECK(outcome.out.empty());
  CHECK(outcome.err ==
        "raster: error: --bench expects a whole number from 1 to 10, got '0' (see --help)\n");
}

TEST_CASE("run_command_line turns any other exception into one line on err and status 1",
          "[common][cli][run]") {
  const Outcome failed = run({}, [](const CliArguments&) -> int {
    throw std::runtime_error("cannot open scene 'x.scene'");
  });
  CHECK(failed.status == 1);
  CHECK(failed.out.empty());
  CHECK(failed.err == "raster: error: cannot open scene 'x.scene'\n");
  CHECK(lines_of(failed.err).size() == 1);

  const Outcome logic =
      run({}, [](const CliArguments&) -> int { throw std::logic_error("a bug"); });
  CHECK(logic.status == 1);
  CHECK(logic.err == "raster: error: a bug\n");
}

TEST_CASE("Every help text ends with the exit statuses all programs share", "[common][cli]") {
  const std::string help = raster_like().help_text();
  CHECK_THAT(help, Catch::EndsWith(std::string(exit_status_help) + "\n"));
  CHECK_THAT(help, Catch::Contains("0 success") && Catch::Contains("2 usage error"));
}

TEST_CASE("A name list keeps valid names in order and refuses empty, unknown and repeated names",
          "[common][cli][names]") {
  const std::vector<std::string> valid{"alpha", "beta", "gamma"};
  CHECK(parse_name_list("only", "beta", valid) == std::vector<std::string>{"beta"});
  CHECK(parse_name_list("only", "gamma,alpha", valid) ==
        std::vector<std::string>{"gamma", "alpha"});
  // A leading comma and a trailing comma are refused alike, as is a doubled one.
  for (const char* list : {",beta", "beta,", "alpha,,beta", ",", ""}) {
    INFO("--only '" << list << "'");
    CHECK_THROWS_AS(parse_name_list("only", list, valid), UsageError);
    CHECK_THROWS_WITH(parse_name_list("only", list, valid), Catch::Contains("empty name"));
  }
  CHECK_THROWS_WITH(parse_name_list("only", "alpha,delta", valid),
                    "--only: unknown name 'delta' (valid: alpha, beta, gamma)");
  CHECK_THROWS_WITH(parse_name_list("only", "beta,alpha,beta", valid),
                    "--only: 'beta' is named twice");
}

TEST_CASE("run_command_line fails with status 1 and the reason when standard output is full",
          "[common][cli][run][standard_output]") {
  std::ofstream full("/dev/full");
  REQUIRE(full.is_open());
  std::ostringstream err;
  const Argv args({"--list"});
  const int status = run_command_line(raster_like(), args.argc(), args.argv(), full, err,
                                      [&](const CliArguments&) {
                                        full << "results the user asked for\n";
                                        return 0;
                                      });
  CHECK(status == exit_failure);
  CHECK(err.str() ==
        "raster: error: cannot write the results to standard output: No space left on device\n");
}

namespace {

// The status and the error lines of a run whose standard output is full.
std::pair<int, std::string> run_into_full_output(
    std::initializer_list<const char*> words,
    const std::function<int(std::ostream& out, const CliArguments&)>& body) {
  std::ofstream full("/dev/full");
  std::ostringstream err;
  const Argv args(words);
  full << "partial";
  const int status = run_command_line(raster_like(), args.argc(), args.argv(), full, err,
                                      [&](const CliArguments& a) { return body(full, a); });
  return {status, err.str()};
}

}  // namespace

TEST_CASE(
    "run_command_line keeps a usage error's status and its one line when standard output also "
    "fails",
    "[common][cli][run][standard_output]") {
  const auto [status, err] =
      run_into_full_output({"--bogus"}, [](std::ostream&, const CliArguments&) { return 0; });
  CHECK(status == exit_usage);
  CHECK(err == "raster: error: unknown option '--bogus' (see --help)\n");
}

TEST_CASE(
    "run_command_line prints one error line for a failure that also leaves standard output "
    "unwritten",
    "[common][cli][run][standard_output]") {
  const auto [status, err] =
      run_into_full_output({"--list"}, [](std::ostream& out, const CliArguments&) -> int {
        out << std::string(1 << 16, 'x') << std::flush;
        throw std::runtime_error("-: cannot write the picture: No space left on device");
      });
  CHECK(status == exit_failure);
  CHECK(err == "raster: error: -: cannot write the picture: No space left on device\n");
}

TEST_CASE("run_command_line escapes control, format and separator characters of a message",
          "[common][cli][run]") {
  std::ostringstream out, err;
  const Argv args({"--\x1b]0;title\x07\n", "x"});
  CHECK(run_command_line(raster_like(), args.argc(), args.argv(), out, err,
                         [](const CliArguments&) { return 0; }) == exit_usage);
  CHECK(err.str() == "raster: error: unknown option '--\\x1B]0;title\\x07\\x0A' (see --help)\n");
  std::ostringstream err2;
  const Argv none({"--list"});
  run_command_line(
      raster_like(), none.argc(), none.argv(), out, err2,
      [](const CliArguments&) -> int { throw std::runtime_error("a\u2028b\u202Ec\u061Cd"); });
  CHECK(err2.str() == "raster: error: a\\xE2\\x80\\xA8b\\xE2\\x80\\xAEc\\xD8\\x9Cd\n");
}

}  // namespace tri
