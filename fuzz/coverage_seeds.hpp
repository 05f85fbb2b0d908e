/// @file
/// The seed corpus of fuzz_coverage, as code, in the layout of rasterizer_input.hpp:
/// fuzz_seed_writer writes them to fuzz/corpus/fuzz_coverage/, and a regression test checks that
/// the files there still match. The regression tests also replay fuzz_rasterizers' seeds through
/// the coverage checks.
#pragma once

#include <vector>

#include "fuzz/rasterizer_seeds.hpp"

namespace tri::fuzz {

/// Every seed of fuzz_coverage: the scenes that once broke the exact-area algorithms (vertices a
/// subnormal distance apart, a product of differences below the least normal double), nearly
/// parallel sides at ±2^30, a canvas covered whole, and grid triangles alone and together.
std::vector<NamedSeed> coverage_seeds();

}  // namespace tri::fuzz
