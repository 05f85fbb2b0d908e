/// @file
/// The seed corpus of fuzz_rasterizers, as code: each seed is a named input in the layout of
/// rasterizer_input.hpp. fuzz_seed_writer writes them to fuzz/corpus/fuzz_rasterizers/, and a
/// regression test checks that the files there still match, so the corpus follows the layout.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace tri::fuzz {

/// One seed: a file name (no folder) and its bytes.
struct NamedSeed {
  std::string name;
  std::vector<std::uint8_t> bytes;
};

/// Every seed of fuzz_rasterizers: the hard cases of
/// @ref design_hard_cases "docs/DESIGN.md section 7" on small canvases, as raw doubles and as
/// interesting values, including NaN, infinities and values beyond ±2^30.
std::vector<NamedSeed> rasterizer_seeds();

}  // namespace tri::fuzz
