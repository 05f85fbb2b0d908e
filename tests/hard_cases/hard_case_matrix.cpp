// Writes the hard-case matrix: CSV (the expected file the tests compare with) and the Markdown
// page of the docs site.
#include <iostream>

#include "cli.hpp"
#include "hard_cases.hpp"
#include "image_io.hpp"
#include "registry.hpp"

namespace {

void write_text(const std::string& path, const std::string& text) {
  const auto* bytes = reinterpret_cast<const std::uint8_t*>(text.data());
  tri::write_file_atomically(path, std::span<const std::uint8_t>(bytes, text.size()));
  std::cout << "wrote " << path << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  const tri::CommandLine command_line(
      "hard_case_matrix",
      "Runs every registered algorithm on every hard case (docs/DESIGN.md section 7) against\n"
      "the exact oracle and writes the matrix: --out DIR writes DIR/hard_cases.md for the docs\n"
      "site, --csv FILE the numbers the tests pin (tests/hard_cases_expected.csv).",
      {{"out", "DIR", "folder for hard_cases.md"}, {"csv", "FILE", "write the CSV to FILE"}});
  return tri::run_command_line(
      command_line, argc, argv, std::cout, std::cerr, [](const tri::CliArguments& args) {
        if (!args.has("out") && !args.has("csv")) {
          throw tri::UsageError("give --out DIR, --csv FILE or both");
        }
        const auto cases = tri::hard_cases::all_cases();
        const auto outcomes = tri::hard_cases::run_all(tri::registered_algorithms());
        if (const auto dir = args.value("out")) {
          write_text(*dir + "/hard_cases.md", tri::hard_cases::to_markdown(outcomes, cases));
        }
        if (const auto csv = args.value("csv")) {
          write_text(*csv, tri::hard_cases::to_csv(outcomes));
        }
        return 0;
      });
}
