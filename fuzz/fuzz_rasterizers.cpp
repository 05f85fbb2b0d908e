// libFuzzer target: every input picks a registered algorithm, a small canvas and up to four
// triangles (see rasterizer_input.hpp), and the algorithm must keep the promises that
// rasterizer_check.hpp lists.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "fuzz/findings_abort.hpp"
#include "fuzz/rasterizer_check.hpp"
#include "fuzz/rasterizer_input.hpp"
#include "measure/registry.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // Read once: the registry is the same for every input.
  static const std::vector<tri::TriangleAlgorithm> algorithms = tri::registered_algorithms();
  if (algorithms.empty()) return 0;
  const tri::fuzz::RasterizerInput input =
      tri::fuzz::decode_rasterizer_input(std::span<const std::uint8_t>(data, size));
  const tri::TriangleAlgorithm& algorithm =
      algorithms[input.algorithm_selector % algorithms.size()];
  tri::fuzz::abort_on_findings(tri::fuzz::check_rasterizer(algorithm, input));
  return 0;
}
