#include "chapters/09_anti_aliasing/sampling.hpp"

#include <stdexcept>

#include "chapters/07_exact_coverage/coverage_oracle.hpp"
#include "chapters/07_exact_coverage/fixed_point.hpp"
#include "chapters/09_anti_aliasing/area_oracle.hpp"

namespace tri::ch09 {
namespace {

// Vulkan's standard sample locations, in 1/16 pixel from the pixel's top-left
// corner with y down, as the Vulkan specification lists them.
constexpr int standard_2[][2] = {{12, 12}, {4, 4}};
constexpr int standard_4[][2] = {{6, 2}, {14, 6}, {2, 10}, {10, 14}};
constexpr int standard_8[][2] = {{9, 5},  {7, 11}, {13, 9},  {5, 3},
                                 {3, 13}, {1, 7},  {11, 15}, {15, 1}};
constexpr int standard_16[][2] = {{9, 9},   {7, 5},  {5, 10},  {12, 7}, {3, 6}, {10, 13},
                                  {13, 11}, {11, 3}, {6, 14},  {8, 1},  {4, 2}, {2, 12},
                                  {0, 8},   {15, 4}, {14, 15}, {1, 0}};

template <std::size_t N>
SamplePattern from_top_left_sixteenths(std::string name, const int (&locations)[N][2]) {
  SamplePattern pattern{std::move(name), {}};
  for (const auto& l : locations) {
    // From the corner, y down, in 1/16 -> from the centre, y up, in 1/32.
    pattern.offsets.push_back({2 * l[0] - 16, 16 - 2 * l[1]});
  }
  return pattern;
}

}  // namespace

SamplePattern regular_grid(int n) {
  if (n < 1 || 16 % n != 0) throw std::invalid_argument("regular_grid: n must divide 16");
  SamplePattern pattern{"grid_" + std::to_string(n) + "x" + std::to_string(n), {}};
  const int step = sample_units / n;  // in 1/32 pixel
  for (int l = 0; l < n; ++l) {
    for (int k = 0; k < n; ++k) {
      pattern.offsets.push_back(
          {-sample_units / 2 + step / 2 + k * step, -sample_units / 2 + step / 2 + l * step});
    }
  }
  return pattern;
}

SamplePattern standard_pattern(int count) {
  switch (count) {
    case 2:
      return from_top_left_sixteenths("standard_2", standard_2);
    case 4:
      return from_top_left_sixteenths("standard_4", standard_4);
    case 8:
      return from_top_left_sixteenths("standard_8", standard_8);
    case 16:
      return from_top_left_sixteenths("standard_16", standard_16);
    default:
      throw std::invalid_argument("standard_pattern: count must be 2, 4, 8 or 16");
  }
}

// [listing sampled_coverage]
double sampled_coverage(const Triangle& triangle, glm::ivec2 pixel, const SamplePattern& pattern) {
  require_on_oracle_grid(triangle);
  return snapped_sampled_coverage(triangle, pixel, pattern);  // snapping leaves it as it is
}

double snapped_sampled_coverage(const Triangle& triangle, glm::ivec2 pixel,
                                const SamplePattern& pattern) {
  // Snapped and scaled by 32, the samples are whole points, where chapter 07's oracle decides
  // them exactly (a vertex at 2^30 becomes a multiple of 1/8 near 2^35: exact in a double).
  Triangle scaled;
  for (std::size_t k = 0; k < 3; ++k) {
    const ch07::SubpixelPoint snapped = ch07::snap_to_subpixel(triangle[k], oracle_subpixel_bits);
    constexpr double to_samples = double{sample_units} / (1 << oracle_subpixel_bits);
    scaled[k] =
        glm::dvec2(static_cast<double>(snapped.x), static_cast<double>(snapped.y)) * to_samples;
  }
  int inside = 0;
  for (const glm::ivec2 offset : pattern.offsets) {
    inside += ch07::oracle_covers(scaled, pixel * sample_units + offset) ? 1 : 0;
  }
  return static_cast<double>(inside) / static_cast<double>(pattern.offsets.size());
}
// [/listing]

}  // namespace tri::ch09
