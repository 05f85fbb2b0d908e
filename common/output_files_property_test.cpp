// OutputTransaction through its public API on seeded random sets of outputs: committed, every
// target holds exactly its bytes; abandoned, every earlier file is as it was and no new one
// exists; either way no temporary is left beside them.
#include <catch2/catch.hpp>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "common/output_files.hpp"
#include "common/random.hpp"

namespace tri {
namespace {

namespace fs = std::filesystem;

std::vector<std::uint8_t> read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<std::uint8_t> random_bytes(Random& random) {
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(random.integer(0, 3000)));
  for (auto& b : bytes) b = static_cast<std::uint8_t>(random.integer(0, 255));
  return bytes;
}

// Every regular file below the folder with its bytes.
std::map<fs::path, std::vector<std::uint8_t>> files_below(const fs::path& folder) {
  std::map<fs::path, std::vector<std::uint8_t>> files;
  for (const auto& entry : fs::recursive_directory_iterator(folder)) {
    if (entry.is_regular_file()) files[entry.path()] = read_bytes(entry.path());
  }
  return files;
}

}  // namespace

TEST_CASE("Seeded random output transactions replace all their files together or none",
          "[common][output_files]") {
  const std::uint64_t trial_seed = 57;  // its address names this run's folder
  const fs::path folder =
      fs::temp_directory_path() / ("output_files_property_test_" +
                                   std::to_string(reinterpret_cast<std::uintptr_t>(&trial_seed)));
  Random random(trial_seed);
  for (int trial = 0; trial < 40; ++trial) {
    CAPTURE(trial);
    fs::remove_all(folder);
    fs::create_directories(folder);
    // Earlier files, some of which the outputs replace.
    for (int k = 0; k < 4; ++k) {
      std::ofstream(folder / ("f" + std::to_string(k)), std::ios::binary) << "earlier " << k;
    }
    const auto before = files_below(folder);
    // One to five outputs: earlier files, new files, files in folders still to be made, and
    // standard output.
    std::map<fs::path, std::vector<std::uint8_t>> outputs;
    std::optional<std::vector<std::uint8_t>> standard_output;
    const int count = random.integer(1, 5);
    for (int k = 0; k < count; ++k) {
      const int kind = random.integer(0, 3);
      if (kind == 3 && !standard_output) {
        standard_output = random_bytes(random);
        continue;
      }
      const std::string name = "f" + std::to_string(random.integer(0, 7));
      outputs[kind == 2 ? folder / ("sub" + std::to_string(k)) / name : folder / name] =
          random_bytes(random);
    }
    const bool commit = random.integer(0, 2) != 0;
    std::ostringstream out;
    {
      OutputTransaction transaction(&out);
      for (const auto& [path, bytes] : outputs) transaction.stage(path, bytes);
      if (standard_output) transaction.stage(standard_output_name, *standard_output);
      if (commit) transaction.commit();
    }
    auto expected = before;
    if (commit) {
      for (const auto& [path, bytes] : outputs) expected[path] = bytes;
    }
    CHECK(files_below(folder) == expected);  // nothing else: no temporary left
    const std::string written = out.str();
    CHECK(written == (commit && standard_output
                          ? std::string(standard_output->begin(), standard_output->end())
                          : std::string()));
  }
  fs::remove_all(folder);
}

}  // namespace tri
