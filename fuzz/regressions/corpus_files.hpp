// What the regression suites share: where the repository's seed corpus lies, and reading a seed.
#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

namespace tri::fuzz {

/// The repository's fuzz/corpus, one folder per target.
inline const std::filesystem::path corpus_folder = TUTORIAL_FUZZ_CORPUS;

/// The bytes of one seed file.
inline std::vector<std::uint8_t> read_bytes(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

}  // namespace tri::fuzz
