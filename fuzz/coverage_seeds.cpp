#include "fuzz/coverage_seeds.hpp"

#include <array>
#include <string>

#include "fuzz/rasterizer_input.hpp"

namespace tri::fuzz {
namespace {

constexpr double limit = max_scene_coordinate;
constexpr double subnormal = 1e-310;
constexpr double least = 4.9406564584124654e-324;  // 2^-1074

// The selector picks the first algorithm to try (0 area_cells, 1 area_cells_over, 2.. sampling);
// the regression test replays every seed with every coverage algorithm.
NamedSeed raw(std::string name, std::uint8_t selector, int size, const Triangle& t) {
  return {std::move(name),
          RasterizerInputWriter(selector, size, size).raw(t, colors::white).bytes()};
}

}  // namespace

std::vector<NamedSeed> coverage_seeds() {
  const Triangle a = {{{1.5, 2.25}, {13.75, 4}, {6.125, 14.5}}};
  const Triangle b = {{{13.75, 4}, {15.5, 15}, {6.125, 14.5}}};  // shares an edge with a
  const Triangle c = {{{0.25, 0.25}, {9, 1.5}, {3, 7.75}}};
  InterestingValue off_grid{Base::subnormal, 0, 0};  // 1e-310: a subnormal off the grid
  auto g = [](int whole) {
    return InterestingValue{Base::zero, static_cast<std::int8_t>(whole), 0};
  };
  return {
      raw("subnormal_apart_over", 1, 16, {{{15, 0}, {subnormal, subnormal}, {0, 15}}}),
      raw("subnormal_apart_summed", 0, 16, {{{15, 0}, {0, 0}, {subnormal, 15}}}),
      raw("least_double_apart", 0, 16, {{{0, 0}, {10, 5}, {least, 10}}}),
      raw("product_below_least_normal", 1, 16, {{{0.125, 3e-308}, {0, 0}, {0, 12}}}),
      raw("nearly_parallel_at_limit", 0, 16, {{{-limit, 0}, {limit, 0}, {limit, 1.0 / 256}}}),
      raw("covering_whole_canvas", 4, 16, {{{-limit, -limit}, {limit, -limit}, {0, limit}}}),
      raw("grid_triangle_over", 1, 16, a),
      raw("grid_triangle_standard_16", 10, 16, c),
      {"interesting_subnormal_vertex",
       RasterizerInputWriter(0, 16, 16)
           .interesting({g(14), g(1), off_grid, off_grid, g(2), g(13)}, colors::white)
           .bytes()},
      {"grid_mesh_summed", RasterizerInputWriter(0, 16, 16)
                               .raw(a, colors::white)
                               .raw(b, colors::white)
                               .raw(c, colors::white)
                               .bytes()},
      {"grid_mesh_over", RasterizerInputWriter(1, 16, 16)
                             .raw(a, colors::white)
                             .raw(b, colors::white)
                             .raw(c, colors::white)
                             .bytes()},
      {"grid_mesh_grid_4x4",
       RasterizerInputWriter(4, 12, 16).raw(a, colors::white).raw(b, colors::white).bytes()},
  };
}

}  // namespace tri::fuzz
