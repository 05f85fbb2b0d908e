// Writes the seed corpora of fuzz_rasterizers (rasterizer_seeds.cpp) and fuzz_coverage
// (coverage_seeds.cpp) into a folder, by default the repository's fuzz/corpus, one subfolder per
// target. Run it after changing the input layout.
#include <filesystem>
#include <iostream>

#include "common/cli.hpp"
#include "common/output_files.hpp"
#include "fuzz/coverage_seeds.hpp"
#include "fuzz/rasterizer_seeds.hpp"

int main(int argc, char** argv) {
  const tri::CommandLine command_line(
      "fuzz_seed_writer",
      "Writes the seed corpora of fuzz_rasterizers and fuzz_coverage, one file per seed.",
      {{"out", "FOLDER",
        "the corpus folder, one subfolder per target (default: " TUTORIAL_FUZZ_CORPUS ")"}});
  return tri::run_command_line(
      command_line, argc, argv, std::cout, std::cerr, [](const tri::CliArguments& arguments) {
        const std::filesystem::path folder = arguments.value_or("out", TUTORIAL_FUZZ_CORPUS);
        // The corpora are replaced as one set, so a failure leaves the previous seeds as they were.
        tri::OutputTransaction files;
        int written = 0;
        for (const auto& [target, seeds] :
             {std::pair{"fuzz_rasterizers", tri::fuzz::rasterizer_seeds()},
              std::pair{"fuzz_coverage", tri::fuzz::coverage_seeds()}}) {
          tri::check_output_folder(folder / target);
          for (const tri::fuzz::NamedSeed& seed : seeds) {
            files.stage(folder / target / seed.name, seed.bytes);
            ++written;
          }
        }
        files.commit();
        std::cout << "wrote " << written << " seeds to " << folder.string() << '\n';
        return 0;
      });
}
