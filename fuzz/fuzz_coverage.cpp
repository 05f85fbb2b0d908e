// libFuzzer target: every input picks one of chapter 09's coverage algorithms, a canvas of at most
// 16 x 16 and up to four triangles (the layout of rasterizer_input.hpp), and the algorithm must
// keep the promises that coverage_check.hpp lists.

#include <cstddef>
#include <cstdint>
#include <span>

#include "chapters/09_anti_aliasing/area_algorithms.hpp"
#include "fuzz/coverage_check.hpp"
#include "fuzz/findings_abort.hpp"
#include "fuzz/rasterizer_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto algorithms = tri::ch09::area_algorithms();
  const tri::fuzz::RasterizerInput input = tri::fuzz::coverage_input(
      tri::fuzz::decode_rasterizer_input(std::span<const std::uint8_t>(data, size)));
  const tri::ch09::AreaAlgorithm& algorithm =
      algorithms[input.algorithm_selector % algorithms.size()];
  tri::fuzz::abort_on_findings(tri::fuzz::check_coverage(algorithm, input));
  return 0;
}
