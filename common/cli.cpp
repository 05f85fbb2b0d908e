#include "common/cli.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <exception>
#include <sstream>

#include "common/printable_text.hpp"

namespace tri {

std::optional<std::string> CliArguments::value(std::string_view name) const {
  const auto it = values_.find(name);
  if (it == values_.end()) return std::nullopt;
  return it->second;
}

std::string CliArguments::value_or(std::string_view name, std::string_view fallback) const {
  return value(name).value_or(std::string(fallback));
}

std::optional<long long> CliArguments::integer(std::string_view name, long long low,
                                               long long high) const {
  const auto text = value(name);
  if (!text) return std::nullopt;
  long long result = 0;
  const auto [end, error] = std::from_chars(text->data(), text->data() + text->size(), result);
  if (error != std::errc() || end != text->data() + text->size() || result < low || result > high) {
    throw UsageError("--" + std::string(name) + " expects a whole number from " +
                     std::to_string(low) + " to " + std::to_string(high) + ", got '" + *text + "'");
  }
  return result;
}

CommandLine::CommandLine(std::string program, std::string summary, std::vector<CliOption> options)
    : program_(std::move(program)), summary_(std::move(summary)), options_(std::move(options)) {}

const CliOption* CommandLine::find(std::string_view name) const {
  for (const auto& option : options_) {
    if (option.name == name) return &option;
  }
  return nullptr;
}

CliArguments CommandLine::parse(int argc, const char* const* argv) const {
  CliArguments args;
  for (int i = 1; i < argc; ++i) {
    const std::string_view word = argv[i];
    if (word == "--help" || word == "-h") {
      args.help_ = true;
      continue;
    }
    if (!word.starts_with("--")) {
      throw UsageError("unexpected argument '" + std::string(word) + "'");
    }
    const std::string_view name = word.substr(2);
    const CliOption* option = find(name);
    if (option == nullptr) throw UsageError("unknown option '" + std::string(word) + "'");
    if (args.has(name)) throw UsageError("option '" + std::string(word) + "' given twice");
    if (option->value_name.empty()) {
      args.values_.emplace(std::string(name), std::string());
      continue;
    }
    // "--scene --list" is a forgotten value, not a scene named "--list".
    if (i + 1 >= argc || std::string_view(argv[i + 1]).starts_with("--")) {
      throw UsageError("option '" + std::string(word) + "' needs a value (" + option->value_name +
                       ")");
    }
    if (argv[i + 1][0] == '\0') {
      throw UsageError("option '" + std::string(word) + "' needs a non-empty value (" +
                       option->value_name + ")");
    }
    args.values_.emplace(std::string(name), std::string(argv[++i]));
  }
  return args;
}

std::string CommandLine::help_text() const {
  std::ostringstream text;
  text << "Usage: " << program_ << " [options]\n\n" << summary_ << "\n\nOptions:\n";
  text << "  --help, -h              print this help and exit\n";
  for (const auto& option : options_) {
    std::string left = "--" + option.name;
    if (!option.value_name.empty()) left += " " + option.value_name;
    text << "  " << left;
    for (std::size_t pad = left.size(); pad < 22; ++pad) text << ' ';
    text << "  " << option.help << "\n";
  }
  text << "\n" << exit_status_help << "\n";
  return text.str();
}

std::string comma_separated(const std::vector<std::string>& names) {
  std::string joined;
  for (const auto& n : names) joined += (joined.empty() ? "" : ", ") + n;
  return joined;
}

std::vector<std::string> parse_name_list(std::string_view option, std::string_view list,
                                         const std::vector<std::string>& valid) {
  std::vector<std::string> names;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = std::min(list.find(',', start), list.size());
    const std::string name(list.substr(start, comma - start));
    if (name.empty()) {
      throw UsageError("--" + std::string(option) + " '" + std::string(list) +
                       "' has an empty name (a leading, trailing or doubled comma)");
    }
    if (std::find(valid.begin(), valid.end(), name) == valid.end()) {
      throw UsageError("--" + std::string(option) + ": unknown name '" + name +
                       "' (valid: " + comma_separated(valid) + ")");
    }
    if (std::find(names.begin(), names.end(), name) != names.end()) {
      throw UsageError("--" + std::string(option) + ": '" + name + "' is named twice");
    }
    names.push_back(name);
    if (comma == list.size()) return names;
    start = comma + 1;
  }
}

int finish_standard_output(std::string_view program, std::ostream& out, std::ostream& err,
                           int status) {
  errno = 0;
  out.flush();
  // A run that failed has said why in its one line; a failed flush adds no second one.
  if (out || status != exit_success) return status;
  const int error = errno;
  err << program << ": error: cannot write the results to standard output: "
      << (error != 0 ? std::strerror(error) : "write failed") << "\n";
  return status == exit_success ? exit_failure : status;
}

int run_command_line(const CommandLine& command_line, int argc, const char* const* argv,
                     std::ostream& out, std::ostream& err,
                     const std::function<int(const CliArguments&)>& body) {
  const int status = [&] {
    try {
      const CliArguments args = command_line.parse(argc, argv);
      if (args.help_requested()) {
        out << command_line.help_text();
        return exit_success;
      }
      return body(args);
    } catch (const UsageError& e) {
      err << command_line.program() << ": error: " << printable_text(e.what()) << " (see --help)\n";
      return exit_usage;
    } catch (const std::exception& e) {
      err << command_line.program() << ": error: " << printable_text(e.what()) << "\n";
      return exit_failure;
    }
  }();
  return finish_standard_output(command_line.program(), out, err, status);
}

}  // namespace tri
