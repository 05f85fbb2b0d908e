#include "chapters/08_fast_exact/instruction_sets.hpp"

#include <catch2/catch.hpp>

#include <cstdint>
#include <initializer_list>
#include <vector>

#include "chapters/08_fast_exact/batched.hpp"
#include "chapters/08_fast_exact/narrow_canvases.hpp"
#include "chapters/08_fast_exact/spans.hpp"
#include "chapters/08_fast_exact/test_triangles.hpp"

using tri::Canvas;
using tri::SceneTriangle;
using tri::ch08::InstructionSet;
using tri::ch08::testing::overlapping_scene;
using tri::ch08::testing::same_canvas;

namespace {

// Calls check(set, seed) for every set this host runs but the portable one (the copies compared
// with the fallback) and every seed, both named in a failed check's message.
template <class Check>
void for_each_wider_copy(std::initializer_list<std::uint64_t> seeds, Check&& check) {
  for (const InstructionSet set : tri::ch08::all_instruction_sets) {
    if (set == InstructionSet::portable || !tri::ch08::host_runs(set)) continue;
    INFO("copy " << static_cast<int>(set));
    for (const std::uint64_t seed : seeds) {
      INFO("seed " << seed);
      check(set, seed);
    }
  }
}

// The scene drawn triangle by triangle with fill_spans's copy for `set`, into every writer.
struct SpanCanvases {
  Canvas rgba, counted;
  tri::ch08::IndexCanvas index;
  tri::ch08::MaskCanvas mask;
};

SpanCanvases spans_drawn(const std::vector<SceneTriangle>& scene, int size, InstructionSet set) {
  SpanCanvases c{Canvas(size, size), Canvas(size, size), {size, size}, {size, size}};
  c.counted.enable_write_counts();
  for (std::size_t i = 0; i < scene.size(); ++i) {
    const auto setup = tri::ch08::setup_triangle(scene[i].vertices, size, size);
    if (!setup) continue;
    tri::ch08::RowWriter rows(c.rgba, scene[i].color);
    tri::ch08::CountingWriter counting(c.counted, scene[i].color);
    tri::ch08::IndexWriter index(c.index, static_cast<std::uint8_t>(1 + i % 255));
    tri::ch08::MaskWriter mask(c.mask);
    tri::ch08::fill_spans(*setup, rows, set);
    tri::ch08::fill_spans(*setup, counting, set);
    tri::ch08::fill_spans(*setup, index, set);
    tri::ch08::fill_spans(*setup, mask, set);
  }
  return c;
}

bool same_narrow(const SpanCanvases& a, const SpanCanvases& b, int size) {
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      if (a.index.index(x, y) != b.index.index(x, y)) return false;
      if (a.mask.covered(x, y) != b.mask.covered(x, y)) return false;
    }
  }
  return true;
}

}  // namespace

TEST_CASE("The host runs the portable copies, and the widest set it runs is one it runs",
          "[08_fast_exact][step3]") {
  CHECK(tri::ch08::host_runs(InstructionSet::portable));
  CHECK(tri::ch08::host_runs(tri::ch08::widest_instruction_set()));
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
  CHECK(tri::ch08::host_runs(InstructionSet::avx2) == (__builtin_cpu_supports("avx2") != 0));
#else
  CHECK_FALSE(tri::ch08::host_runs(InstructionSet::avx2));
#endif
}

TEST_CASE("Every copy of the span fill the host runs writes the portable copy's pixels",
          "[08_fast_exact][step3]") {
  for_each_wider_copy({301, 302, 303}, [](InstructionSet set, std::uint64_t seed) {
    // Odd sizes: spans that end at every offset of a 32-byte store, at the canvas's right edge.
    for (const int size : {37, 100}) {
      const auto scene = overlapping_scene(seed, 300, size);
      const SpanCanvases portable = spans_drawn(scene, size, InstructionSet::portable);
      const SpanCanvases forced = spans_drawn(scene, size, set);
      CHECK(same_canvas(forced.rgba, portable.rgba));
      CHECK(same_canvas(forced.counted, portable.counted));
      CHECK(same_narrow(forced, portable, size));
    }
  });
}

TEST_CASE("Every copy of the batched lanes the host runs draws the portable copy's pixels",
          "[08_fast_exact][step10]") {
  for_each_wider_copy({1001, 1002, 1003}, [](InstructionSet set, std::uint64_t seed) {
    const auto scene = overlapping_scene(seed, 400, 61);
    for (const bool counting : {false, true}) {
      const auto drawn = [&](InstructionSet copy) {
        return tri::ch08::testing::drawn_on(61, 61, counting, [&](Canvas& canvas) {
          tri::ch08::draw_batch_batched_with(canvas, scene, copy);
        });
      };
      CHECK(same_canvas(drawn(set), drawn(InstructionSet::portable)));
    }
  });
}
