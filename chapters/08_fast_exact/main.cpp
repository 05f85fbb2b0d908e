// Chapter 08's figures: which edges each pixel passes (the one-branch test), the spans of a
// sliver against its bounding box, a triangle's 8x8 blocks by class, which path the hybrid takes
// per triangle, and the bands the threads share out.
#include <array>
#include <cmath>
#include <vector>

#include "blocks.hpp"
#include "figures.hpp"
#include "random.hpp"
#include "simd.hpp"
#include "spans.hpp"
#include "threaded.hpp"
#include "triangle_setup.hpp"

namespace {

using tri::Canvas;
using tri::Color;
using tri::Triangle;
using tri::ch07::PixelRange;

constexpr Color dark{40, 40, 48, 255};
constexpr Color box_gray{80, 80, 90, 255};

Color mix(Color a, Color b, int percent_b) {
  const auto channel = [&](int i) {
    return static_cast<std::uint8_t>((a[i] * (100 - percent_b) + b[i] * percent_b) / 100);
  };
  return {channel(0), channel(1), channel(2), 255};
}

void fill_rect(Canvas& canvas, const PixelRange& r, Color color) {
  for (int y = r.first_y; y <= r.last_y; ++y) {
    for (int x = r.first_x; x <= r.last_x; ++x) canvas.put_pixel(x, y, color);
  }
}

// Step 2: each candidate pixel coloured by the edges it passes; a channel goes dark for each
// failed edge (red: edge 0, green: edge 1, blue: edge 2). White: all three pass, one OR says so.
Canvas edge_signs() {
  Canvas canvas(40, 30, dark);
  const auto setup = tri::ch08::setup_triangle({{{3.5, 4.25}, {36.75, 9.5}, {14.25, 27}}}, 40, 30);
  const auto& r = setup->range;
  for (int y = r.first_y; y <= r.last_y; ++y) {
    for (int x = r.first_x; x <= r.last_x; ++x) {
      std::array<std::uint8_t, 3> rgb{};
      for (int e = 0; e < 3; ++e) {
        const bool pass =
            setup->edges[static_cast<std::size_t>(e)].at(x - r.first_x, y - r.first_y) >= 0;
        rgb[static_cast<std::size_t>(e)] = pass ? 255 : 70;
      }
      canvas.put_pixel(x, y, Color{rgb[0], rgb[1], rgb[2], 255});
    }
  }
  return canvas;
}

// Step 3: a sliver's bounding box (grey: what a per-pixel loop tests) and its spans, one per
// row, in alternating colours: the only pixels the span walker touches.
Canvas sliver_spans() {
  Canvas canvas(64, 40, dark);
  const auto setup = tri::ch08::setup_triangle({{{2.5, 3.25}, {61, 36.5}, {30.75, 20.5}}}, 64, 40);
  fill_rect(canvas, setup->range, box_gray);
  tri::ch08::SpanWalker walker(*setup);
  for (int y = walker.first_row(); y <= walker.last_row(); ++y, walker.next_row()) {
    const tri::ch08::RowSpan s = walker.span();
    for (int x = s.first; x <= s.last; ++x)
      canvas.put_pixel(x, y, y % 2 == 0 ? tri::colors::cyan : tri::colors::yellow);
  }
  return canvas;
}

// Block borders drawn on a magnified canvas, every `block` source pixels from `origin`.
void draw_block_grid(Canvas& big, int factor, const PixelRange& range, Color color) {
  for (int y = range.first_y * factor; y < (range.last_y + 1) * factor; ++y) {
    for (int x = range.first_x * factor; x < (range.last_x + 1) * factor; ++x) {
      const bool vertical =
          (x / factor - range.first_x) % tri::ch08::block_size == 0 && x % factor == 0;
      const bool horizontal =
          (y / factor - range.first_y) % tri::ch08::block_size == 0 && y % factor == 0;
      if (vertical || horizontal) big.put_pixel(x, y, color);
    }
  }
}

// Step 4: the 8x8 blocks of a triangle's candidate pixels: outside (dark), inside (green, filled
// without a test), partial (amber, each pixel tested; white where covered).
Canvas blocks() {
  constexpr int factor = 8;
  Canvas canvas(72, 56, dark);
  const auto setup =
      tri::ch08::setup_triangle({{{3.25, 2.5}, {69.5, 14.75}, {22.5, 53.25}}}, 72, 56);
  tri::ch08::for_each_block(*setup, [&](const PixelRange& block, tri::ch08::BlockCoverage c) {
    if (c == tri::ch08::BlockCoverage::inside) fill_rect(canvas, block, Color{60, 170, 80, 255});
    if (c == tri::ch08::BlockCoverage::outside) fill_rect(canvas, block, Color{55, 55, 70, 255});
    if (c == tri::ch08::BlockCoverage::partial) {
      for (int y = block.first_y; y <= block.last_y; ++y) {
        for (int x = block.first_x; x <= block.last_x; ++x) {
          canvas.put_pixel(x, y,
                           setup->covers(x, y) ? tri::colors::white : Color{200, 140, 40, 255});
        }
      }
    }
  });
  Canvas big = tri::magnified(canvas, factor);
  draw_block_grid(big, factor, setup->range, Color{20, 20, 20, 255});
  return big;
}

// Step 6: mixed triangles coloured by the path the hybrid takes: magenta for triangles within one
// 8x8 block (lane test), cyan for the rest (spans).
Canvas hybrid_paths() {
  Canvas canvas(160, 120, dark);
  tri::Random random(8);
  for (int i = 0; i < 140; ++i) {
    const double extent = i % 3 == 0 ? random.real(8, 30) : random.real(1, 4);
    const glm::dvec2 centre(random.real(0, 160), random.real(0, 120));
    Triangle t;
    for (auto& v : t) {
      v = centre + glm::dvec2(random.real(-extent, extent), random.real(-extent, extent));
    }
    const auto setup = tri::ch08::setup_triangle(t, 160, 120);
    if (!setup) continue;
    const bool one_block = tri::ch08::fits_one_block(*setup);
    const Color color = mix(one_block ? tri::colors::magenta : tri::colors::cyan,
                            tri::colors::white, random.integer(0, 50));
    tri::ch08::draw_triangle_spans(canvas, t, color);
  }
  return canvas;
}

// Step 7: a scene drawn by two threads; every pixel tinted by the thread that owns its row's
// band (blue: thread 0, orange: thread 1). Each thread draws every triangle, clipped to its
// bands.
Canvas bands() {
  Canvas canvas(128, 96, Color{30, 30, 30, 255});
  tri::Random random(3);
  std::vector<tri::SceneTriangle> scene;
  for (int i = 0; i < 24; ++i) {
    const glm::dvec2 centre(random.real(0, 128), random.real(0, 96));
    const double extent = random.real(10, 40);
    Triangle t;
    for (auto& v : t) {
      v = centre + glm::dvec2(random.real(-extent, extent), random.real(-extent, extent));
    }
    const auto level = static_cast<std::uint8_t>(random.integer(120, 255));
    scene.push_back({t, Color{level, level, level, 255}});
  }
  tri::ch08::draw_batch_on_threads(canvas, scene, 2);
  const std::array<Color, 2> tints{Color{40, 110, 255, 255}, Color{255, 140, 30, 255}};
  for (int y = 0; y < canvas.height(); ++y) {
    const Color tint =
        tints[static_cast<std::size_t>(tri::ch08::bands_for(canvas.height(), 2).owner(y))];
    for (int x = 0; x < canvas.width(); ++x)
      canvas.put_pixel(x, y, mix(canvas.pixel(x, y), tint, 45));
  }
  return canvas;
}

}  // namespace

int main(int argc, char** argv) {
  return tri::run_chapter_program(
      argc, argv, "08_fast_exact",
      "Chapter 08, fast and still exact: which edges each pixel passes (08_edge_signs.png), the\n"
      "spans of a sliver in its bounding box (08_sliver_spans.png), a triangle's 8x8 blocks by\n"
      "class (08_blocks.png), the path the hybrid takes per triangle (08_hybrid_paths.png), and\n"
      "the bands two threads share (08_bands.png).",
      [](tri::FigureWriter& figures) {
        figures.save_png("08_edge_signs", tri::magnified(edge_signs(), 12));
        figures.save_png("08_sliver_spans", tri::magnified(sliver_spans(), 10));
        figures.save_png("08_blocks", blocks());
        figures.save_png("08_hybrid_paths", tri::magnified(hybrid_paths(), 4));
        figures.save_png("08_bands", tri::magnified(bands(), 5));
      });
}
