// Writes the hard-case matrix: CSV (the expected file the tests compare with) and the docs
// site's hard-case page, a Markdown file with one SVG diagram per case next to it.
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "common/cli.hpp"
#include "common/figures.hpp"
#include "common/output_files.hpp"
#include "measure/registry.hpp"
#include "tests/hard_cases/hard_case_diagram.hpp"
#include "tests/hard_cases/hard_case_page.hpp"
#include "measure/hard_cases.hpp"

int main(int argc, char** argv) {
  const tri::CommandLine command_line(
      "hard_case_matrix",
      "Runs every registered algorithm on every hard case (docs/DESIGN.md section 7) against the "
      "exact\n"
      "oracle and writes the matrix: --out DIR writes DIR/hard_cases.md for the docs site and\n"
      "its diagrams DIR/hard_case_NAME.svg,\n"
      "--csv FILE the numbers the tests pin (tests/hard_cases_expected.csv).",
      {{"out", "DIR", "folder for hard_cases.md and hard_case_*.svg"},
       {"csv", "FILE", "write the CSV to FILE"}});
  return tri::run_command_line(
      command_line, argc, argv, std::cout, std::cerr, [](const tri::CliArguments& args) {
        if (!args.has("out") && !args.has("csv")) {
          throw tri::UsageError("give --out DIR, --csv FILE or both");
        }
        // Every output is checked before the run and all are replaced together after it.
        const auto cases = tri::hard_cases::all_cases();
        std::vector<std::filesystem::path> outputs;
        if (const auto dir = args.value("out")) {
          tri::check_output_folder(*dir);
          outputs.push_back(std::filesystem::path(*dir) / "hard_cases.md");
          for (const auto& c : cases) {
            outputs.push_back(std::filesystem::path(*dir) /
                              (tri::hard_cases::diagram_name(c) + ".svg"));
          }
        }
        if (const auto csv = args.value("csv")) outputs.emplace_back(*csv);
        tri::check_outputs(outputs);
        const auto outcomes = tri::hard_cases::run_all(tri::registered_algorithms());
        tri::OutputTransaction files;
        std::size_t next = 0;
        if (args.has("out")) {
          files.stage(outputs[next++],
                      tri::bytes_of_text(tri::hard_cases::to_markdown(outcomes, cases)));
          for (const auto& c : cases) {
            files.stage(outputs[next++], tri::bytes_of_text(tri::hard_cases::diagram_svg(c)));
          }
        }
        if (args.has("csv")) {
          files.stage(outputs[next++], tri::bytes_of_text(tri::hard_cases::to_csv(outcomes)));
        }
        files.commit();
        for (const auto& path : outputs) std::cout << "wrote " << path.string() << "\n";
        return 0;
      });
}
