// Writes the seed corpus of fuzz_rasterizers (rasterizer_seeds.cpp) into a folder, by default
// the repository's fuzz/corpus/fuzz_rasterizers. Run it after changing the input layout.
#include <filesystem>
#include <fstream>
#include <iostream>

#include "cli.hpp"
#include "rasterizer_seeds.hpp"

int main(int argc, char** argv) {
  const tri::CommandLine command_line(
      "fuzz_seed_writer", "Writes the seed corpus of fuzz_rasterizers, one file per seed.",
      {{"out", "FOLDER", "where to write (default: " TUTORIAL_RASTERIZER_CORPUS ")"}});
  return tri::run_command_line(
      command_line, argc, argv, std::cout, std::cerr, [](const tri::CliArguments& arguments) {
        const std::filesystem::path folder = arguments.value_or("out", TUTORIAL_RASTERIZER_CORPUS);
        std::filesystem::create_directories(folder);
        int written = 0;
        for (const tri::fuzz::NamedSeed& seed : tri::fuzz::rasterizer_seeds()) {
          std::ofstream file(folder / seed.name, std::ios::binary);
          file.write(reinterpret_cast<const char*>(seed.bytes.data()),
                     static_cast<std::streamsize>(seed.bytes.size()));
          if (!file) throw std::runtime_error("cannot write " + (folder / seed.name).string());
          ++written;
        }
        std::cout << "wrote " << written << " seeds to " << folder.string() << '\n';
        return 0;
      });
}
