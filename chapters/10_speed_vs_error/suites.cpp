#include "chapters/10_speed_vs_error/suites.hpp"

#include <array>

namespace tri::ch10 {
namespace {

// One scene kind at one suite size: what generate_scene needs besides the canvas and the grid.
struct KindSpec {
  const char* name;
  SceneRecipe::Kind kind;
  int triangles;
  double min_extent;
  double max_extent;
};

// One suite size: its name, its scenes, how it is timed.
struct SizeSpec {
  std::string_view name;
  int side;  // square canvas
  std::array<KindSpec, 7> kinds;
  TimingPlan timing;
  int reference_canvas_sides[2];  // 0: none
};

using Kind = SceneRecipe::Kind;

// From 1-pixel triangles to canvas-sized ones, plus the shapes that break rasterizers: needles,
// a fan around one vertex, a jittered mesh; "mixed" spans every size at once.
constexpr SizeSpec tiny_spec{"tiny",
                             32,
                             {{{"tiny", Kind::random, 20, 0.5, 2},
                               {"medium", Kind::random, 10, 2, 6},
                               {"large", Kind::random, 2, 8, 20},
                               {"slivers", Kind::slivers, 10, 4, 16},
                               {"mesh", Kind::jittered_grid, 32, 0, 0},
                               {"fan", Kind::fan, 16, 0, 0},
                               {"mixed", Kind::random, 10, 0.5, 12}}},
                             {0.0, 1, 1},  // one run, one sample: the tests check the format only
                             {64, 0}};
constexpr SizeSpec quick_spec{"quick",
                              256,
                              {{{"tiny", Kind::random, 4000, 0.5, 2},
                                {"medium", Kind::random, 1000, 4, 16},
                                {"large", Kind::random, 16, 64, 160},
                                {"slivers", Kind::slivers, 1000, 8, 64},
                                {"mesh", Kind::jittered_grid, 4000, 0, 0},
                                {"fan", Kind::fan, 256, 0, 0},
                                {"mixed", Kind::random, 1000, 0.5, 64}}},
                              {0.01, 3, 1 << 20},
                              {512, 4096}};
constexpr SizeSpec full_spec{"full",
                             512,
                             {{{"tiny", Kind::random, 50000, 0.5, 2},
                               {"medium", Kind::random, 10000, 4, 16},
                               {"large", Kind::random, 64, 128, 320},
                               {"slivers", Kind::slivers, 10000, 16, 128},
                               {"mesh", Kind::jittered_grid, 100352, 0, 0},  // 224x224 cells
                               {"fan", Kind::fan, 1024, 0, 0},
                               {"mixed", Kind::random, 10000, 0.5, 128}}},
                             {0.02, 7, 1 << 22},
                             {512, 4096}};

// The sizes in SuiteSize's order.
constexpr std::array<const SizeSpec*, 3> specs{&tiny_spec, &quick_spec, &full_spec};

const SizeSpec& spec_of(SuiteSize size) noexcept {
  const auto i = static_cast<std::size_t>(size);
  return i < specs.size() ? *specs[i] : quick_spec;
}

}  // namespace

std::string_view size_name(SuiteSize size) noexcept {
  return spec_of(size).name;
}

std::string grid_label(int grid_bits) {
  if (grid_bits == 0) return "integer";
  if (grid_bits == 8) return "1/256";
  return "1/2^" + std::to_string(grid_bits);
}

// [listing scene_suite]
std::vector<SuiteScene> scene_suite(SuiteSize size) {
  const SizeSpec& spec = spec_of(size);
  std::vector<SuiteScene> scenes;
  std::uint64_t seed = 9000;  // chapter 10's scenes, distinct from every test's seeds
  for (const int grid_bits : {0, 8}) {
    for (const KindSpec& kind : spec.kinds) {
      const SceneRecipe recipe{.kind = kind.kind,
                               .width = spec.side,
                               .height = spec.side,
                               .triangles = kind.triangles,
                               .min_extent = kind.min_extent,
                               .max_extent = kind.max_extent,
                               .grid_bits = grid_bits,
                               .seed = ++seed};
      scenes.push_back({kind.name, grid_label(grid_bits), recipe, is_mesh(recipe)});
    }
  }
  return scenes;
}
// [/listing]

BenchSettings bench_settings(SuiteSize size) {
  const SizeSpec& spec = spec_of(size);
  BenchSettings settings;
  settings.size = size;
  settings.scenes = scene_suite(size);
  settings.timing = spec.timing;
  for (const int side : spec.reference_canvas_sides) {
    if (side != 0) settings.reference_canvas_sides.push_back(side);
  }
  return settings;
}

}  // namespace tri::ch10
