#include "chapters/10_speed_vs_error/suites.hpp"

#include <array>

namespace tri::ch10 {
namespace {

// One scene kind at one suite size: what generate_scene needs besides the canvas and the grid.
struct KindSize {
  int triangles;
  double min_extent;
  double max_extent;
};

using Kind = SceneRecipe::Kind;

// One scene kind: its name, its generator and its size in each suite, in SuiteSize's order.
struct KindSpec {
  const char* name;
  Kind kind;
  std::array<KindSize, 3> sizes;
};

// From 1-pixel triangles to canvas-sized ones, plus the shapes that break rasterizers: needles,
// a fan around one vertex, a jittered mesh; "mixed" spans every size at once.
constexpr std::array<KindSpec, 7> kinds{{
    {"tiny", Kind::random, {{{20, 0.5, 2}, {4000, 0.5, 2}, {50000, 0.5, 2}}}},
    {"medium", Kind::random, {{{10, 2, 6}, {1000, 4, 16}, {10000, 4, 16}}}},
    {"large", Kind::random, {{{2, 8, 20}, {16, 64, 160}, {64, 128, 320}}}},
    {"slivers", Kind::slivers, {{{10, 4, 16}, {1000, 8, 64}, {10000, 16, 128}}}},
    {"mesh", Kind::jittered_grid, {{{32, 0, 0}, {4000, 0, 0}, {100352, 0, 0}}}},  // 224x224 cells
    {"fan", Kind::fan, {{{16, 0, 0}, {256, 0, 0}, {1024, 0, 0}}}},
    {"mixed", Kind::random, {{{10, 0.5, 12}, {1000, 0.5, 64}, {10000, 0.5, 128}}}},
}};

// One suite size: its name, its canvas, how it is timed.
struct SizeSpec {
  std::string_view name;
  int side;  // square canvas
  TimingPlan timing;
  int reference_canvas_sides[2];  // 0: none
  double user_path_budget_seconds;
};

// The sizes in SuiteSize's order; tiny is timed once with one sample: the tests check the format.
constexpr std::array<SizeSpec, 3> specs{{
    {"tiny", 32, {0.0, 1, 1}, {64, 0}, 0.001},
    {"quick", 256, {0.01, 3, 1 << 20}, {512, 4096}, 0.1},
    {"full", 512, {0.02, 7, 1 << 22}, {512, 4096}, 0.5},
}};

// The index of a size in specs and in every kind's sizes; an unknown size reads as quick.
std::size_t index_of(SuiteSize size) noexcept {
  const auto i = static_cast<std::size_t>(size);
  return i < specs.size() ? i : 1;
}

const SizeSpec& spec_of(SuiteSize size) noexcept {
  return specs[index_of(size)];
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
    for (const KindSpec& kind : kinds) {
      const KindSize& at = kind.sizes[index_of(size)];
      const SceneRecipe recipe{.kind = kind.kind,
                               .width = spec.side,
                               .height = spec.side,
                               .triangles = at.triangles,
                               .min_extent = at.min_extent,
                               .max_extent = at.max_extent,
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
  settings.user_path_budget_seconds = spec.user_path_budget_seconds;
  for (const int side : spec.reference_canvas_sides) {
    if (side != 0) settings.reference_canvas_sides.push_back(side);
  }
  return settings;
}

}  // namespace tri::ch10
