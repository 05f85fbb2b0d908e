// Writes the hard-case matrix: CSV (the expected file the tests compare with) and the Markdown
// page of the docs site.
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "cli.hpp"
#include "hard_cases.hpp"
#include "output_files.hpp"
#include "registry.hpp"

int main(int argc, char** argv) {
  const tri::CommandLine command_line(
      "hard_case_matrix",
      "Runs every registered algorithm on every hard case (DESIGN section 7) against the exact\n"
      "oracle and writes the matrix: --out DIR writes DIR/hard_cases.md for the docs site,\n"
      "--csv FILE the numbers the tests pin (tests/hard_cases_expected.csv).",
      {{"out", "DIR", "folder for hard_cases.md"}, {"csv", "FILE", "write the CSV to FILE"}});
  return tri::run_command_line(
      command_line, argc, argv, std::cout, std::cerr, [](const tri::CliArguments& args) {
        if (!args.has("out") && !args.has("csv")) {
          throw tri::UsageError("give --out DIR, --csv FILE or both");
        }
        // Both outputs are checked before the run and replaced together after it.
        std::vector<std::filesystem::path> outputs;
        if (const auto dir = args.value("out")) {
          tri::check_output_folder(*dir);
          outputs.push_back(std::filesystem::path(*dir) / "hard_cases.md");
        }
        if (const auto csv = args.value("csv")) outputs.emplace_back(*csv);
        tri::check_outputs(outputs);
        const auto cases = tri::hard_cases::all_cases();
        const auto outcomes = tri::hard_cases::run_all(tri::registered_algorithms());
        const std::string markdown = tri::hard_cases::to_markdown(outcomes, cases);
        const std::string csv = tri::hard_cases::to_csv(outcomes);
        tri::OutputTransaction files;
        std::size_t next = 0;
        if (args.has("out")) files.stage(outputs[next++], tri::bytes_of_text(markdown));
        if (args.has("csv")) files.stage(outputs[next++], tri::bytes_of_text(csv));
        files.commit();
        for (const auto& path : outputs) std::cout << "wrote " << path.string() << "\n";
        return 0;
      });
}
