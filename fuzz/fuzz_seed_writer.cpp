// Writes the seed corpus of fuzz_rasterizers (rasterizer_seeds.cpp) into a folder, by default
// the repository's fuzz/corpus/fuzz_rasterizers. Run it after changing the input layout.
#include <filesystem>
#include <iostream>

#include "common/cli.hpp"
#include "common/output_files.hpp"
#include "fuzz/rasterizer_seeds.hpp"

int main(int argc, char** argv) {
  const tri::CommandLine command_line(
      "fuzz_seed_writer", "Writes the seed corpus of fuzz_rasterizers, one file per seed.",
      {{"out", "FOLDER", "where to write (default: " TUTORIAL_RASTERIZER_CORPUS ")"}});
  return tri::run_command_line(
      command_line, argc, argv, std::cout, std::cerr, [](const tri::CliArguments& arguments) {
        const std::filesystem::path folder = arguments.value_or("out", TUTORIAL_RASTERIZER_CORPUS);
        tri::check_output_folder(folder);
        // The corpus is replaced as one set, so a failure leaves the previous seeds as they were.
        tri::OutputTransaction files;
        int written = 0;
        for (const tri::fuzz::NamedSeed& seed : tri::fuzz::rasterizer_seeds()) {
          files.stage(folder / seed.name, seed.bytes);
          ++written;
        }
        files.commit();
        std::cout << "wrote " << written << " seeds to " << folder.string() << '\n';
        return 0;
      });
}
