// Writes the hard-case matrix: CSV (the expected file the tests compare with) and the docs
// site's hard-case page, a Markdown file with one SVG diagram per case next to it.
#include <iostream>

#include "cli.hpp"
#include "figures.hpp"
#include "hard_case_diagram.hpp"
#include "hard_case_page.hpp"
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
      "Runs every registered algorithm on every hard case (docs/DESIGN.md section 7) against the exact\n"
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
        const auto cases = tri::hard_cases::all_cases();
        const auto outcomes = tri::hard_cases::run_all(tri::registered_algorithms());
        if (const auto dir = args.value("out")) {
          tri::FigureWriter figures(*dir, std::cout);
          for (const auto& c : cases) {
            figures.save_svg(tri::hard_cases::diagram_name(c), tri::hard_cases::diagram_svg(c));
          }
          figures.save_text("hard_cases.md", tri::hard_cases::to_markdown(outcomes, cases));
        }
        if (const auto csv = args.value("csv")) {
          write_text(*csv, tri::hard_cases::to_csv(outcomes));
        }
        return 0;
      });
}
