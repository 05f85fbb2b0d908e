// Chapter 08's figures: one edge's value at each pixel (the incremental walk), which edges each
// pixel passes (the one-branch test), a row's eight lanes (the SIMD test), the spans of a
// sliver against its bounding box, a triangle's 8x8 blocks by class, which path the hybrid takes
// per triangle (and close up, which pixels each path tests), the bands the threads share out, the
// bytes of each pixel format, the tiles a scene is binned into and eight triangles' lanes.
#include <array>
#include <string>
#include <vector>

#include "chapters/08_fast_exact/batched.hpp"
#include "chapters/08_fast_exact/blocks.hpp"
#include "chapters/08_fast_exact/incremental.hpp"
#include "chapters/08_fast_exact/simd.hpp"
#include "chapters/08_fast_exact/spans.hpp"
#include "chapters/08_fast_exact/threaded.hpp"
#include "chapters/08_fast_exact/tiled.hpp"
#include "chapters/08_fast_exact/triangle_setup.hpp"
#include "common/figures.hpp"
#include "common/pixel_diagram.hpp"
#include "common/random.hpp"

namespace {

using tri::Canvas;
using tri::Color;
using tri::LabelPlace;
using tri::PixelDiagram;
using tri::PixelMark;
using tri::Triangle;
using tri::ch05::PixelBox;
namespace dc = tri::diagram_colors;

// Okabe–Ito colours lightened towards white, for fills under the centre dots.
constexpr Color light_green{153, 216, 199, 255};
constexpr Color light_vermillion{242, 191, 153, 255};
constexpr Color light_blue{153, 199, 224, 255};
constexpr Color light_purple{235, 201, 220, 255};
constexpr Color light_orange{245, 207, 128, 255};

Color mix(Color a, Color b, int percent_b) {
  const auto channel = [&](int i) {
    return static_cast<std::uint8_t>((a[i] * (100 - percent_b) + b[i] * percent_b) / 100);
  };
  return {channel(0), channel(1), channel(2), 255};
}

// The outer border of a rectangle of pixels.
void outline(PixelDiagram& d, const PixelBox& r, Color color, double width, bool dashed = false) {
  d.frame({r.min.x, r.min.y}, {r.max.x, r.max.y}, color, width, dashed);
}

// A triangle's ideal edges as three segments (the writer cuts them to the diagram).
void edges(PixelDiagram& d, const Triangle& t, double width) {
  for (std::size_t k = 0; k < 3; ++k) d.line(t[k], t[(k + 1) % 3], dc::black, width);
}

// The triangle's three vertices labelled A, B, C (counter-clockwise).
void label_vertices(PixelDiagram& d, const Triangle& t, std::array<LabelPlace, 3> places) {
  d.vertex(t[0], "A", places[0]);
  d.vertex(t[1], "B", places[1]);
  d.vertex(t[2], "C", places[2]);
}

// The triangle's ideal edges and its three labelled vertices.
void draw_triangle(PixelDiagram& d, const Triangle& t, std::array<LabelPlace, 3> places) {
  d.triangle(t[0], t[1], t[2], dc::black);
  label_vertices(d, t, places);
}

// A triangle of random vertices within `extent` of `centre` on each axis.
Triangle triangle_around(tri::Random& random, glm::dvec2 centre, double extent) {
  Triangle t;
  for (auto& v : t) {
    // y before x, one draw a statement: the order the figures were first drawn in, on every
    // compiler.
    const double dy = random.real(-extent, extent);
    const double dx = random.real(-extent, extent);
    v = centre + glm::dvec2(dx, dy);
  }
  return t;
}

// Step 1: one edge's value at every candidate pixel, as the walk reaches it: each value is its left
// neighbour plus step_x and the value below it plus step_y, so a learner can add them by hand.
std::string incremental_values_figure() {
  const Triangle t{{{0.75, 0.5}, {6.5, 1.75}, {2.25, 5.5}}};
  const auto setup = tri::ch08::setup_triangle(t, 8, 7);
  const tri::ch08::EdgeFunction& ab = setup->edges[2];  // edges 0, 1, 2 are BC, CA, AB
  PixelDiagram d({0, 0}, {7, 6}, "Step 1: edge AB's value, one addition per pixel", 58);
  const auto& r = setup->range;
  d.show_centres(false);  // the values sit where the centres would
  tri::ch08::walk_incremental(
      *setup, r, [&](int x, int y, std::int64_t w0, std::int64_t w1, std::int64_t w2) {
        const bool inside = tri::ch08::inside_all_edges(w0, w1, w2);
        d.fill({x, y}, inside ? light_green : w2 >= 0 ? light_blue : light_vermillion);
        d.pixel_text({x, y}, std::to_string(w2));
      });
  d.mark({r.min.x, r.min.y}, PixelMark::square, dc::black);
  outline(d, r, dc::dark_gray, 2, true);
  d.line(t[0], t[1], dc::vermillion, 3);
  d.line(t[1], t[2], dc::black, 1.5);
  d.line(t[2], t[0], dc::black, 1.5);
  label_vertices(d, t, {LabelPlace::below_right, LabelPlace::below_left, LabelPlace::above_right});
  d.legend_fill("covered: all three edge values >= 0", light_green);
  d.legend_fill("AB's value >= 0, another edge's < 0", light_blue);
  d.legend_fill("AB's value < 0: outside edge AB", light_vermillion);
  d.legend_mark("origin pixel: the setup's value " + std::to_string(ab.value), PixelMark::square);
  d.legend_line("edge AB", dc::vermillion);
  d.legend_line("candidate pixels (bounding box)", dc::dark_gray, true);
  d.legend_note("One pixel right adds step_x = " + std::to_string(ab.step_x) +
                "; one row up adds step_y = " + std::to_string(ab.step_y) +
                " (units of 1/256 pixel: the snapped vertices' differences)");
  return d.svg();
}

// Step 2: every candidate pixel by the edges it passes (the setup's edges 0, 1, 2 are BC, CA and
// AB for a counter-clockwise A, B, C); pixels outside the candidate range are never tested.
std::string edge_signs_figure() {
  const Triangle t{{{1.5, 2.25}, {18.75, 5.5}, {7.25, 14}}};
  const auto setup = tri::ch08::setup_triangle(t, 21, 17);
  PixelDiagram d({0, 0}, {20, 16}, "Which edges each candidate pixel passes: (w0 | w1 | w2) >= 0",
                 26);
  const std::array<Color, 3> fails_one{light_blue, light_purple, light_vermillion};
  const auto& r = setup->range;
  int fails_two = 0;
  for (int y = r.min.y; y <= r.max.y; ++y) {
    for (int x = r.min.x; x <= r.max.x; ++x) {
      int failed = 0;
      std::size_t which = 0;
      for (std::size_t e = 0; e < 3; ++e) {
        if (setup->edges[e].at(x - r.min.x, y - r.min.y) < 0) {
          ++failed;
          which = e;
        }
      }
      fails_two += failed == 2;
      d.fill({x, y}, failed == 0 ? light_green : failed == 1 ? fails_one[which] : dc::light_gray);
    }
  }
  outline(d, r, dc::dark_gray, 2, true);
  d.line(t[0], t[1], dc::vermillion);
  d.line(t[1], t[2], dc::blue);
  d.line(t[2], t[0], dc::purple);
  label_vertices(d, t, {LabelPlace::below_right, LabelPlace::below_left, LabelPlace::above_right});
  d.legend_fill("passes all three: drawn", light_green);
  d.legend_fill("fails AB only", light_vermillion);
  d.legend_fill("fails BC only", light_blue);
  d.legend_fill("fails CA only", light_purple);
  if (fails_two > 0) d.legend_fill("fails two (past a vertex)", dc::light_gray);
  d.legend_line("candidate pixels (bounding box)", dc::dark_gray, true);
  d.legend_line("edge AB", dc::vermillion);
  d.legend_line("edge BC", dc::blue);
  d.legend_line("edge CA", dc::purple);
  return d.svg();
}

// Step 3: a sliver's candidate pixels (what steps 1 and 2 test) and its spans, one per row in
// alternating colours: the only pixels the span walker touches.
std::string sliver_spans_figure() {
  const Triangle t{{{1.5, 1.25}, {30.5, 18.5}, {13.75, 11.5}}};
  const auto setup = tri::ch08::setup_triangle(t, 32, 20);
  PixelDiagram d({0, 0}, {31, 19}, "A sliver: one span per row instead of its bounding box", 20);
  const auto& r = setup->range;
  const auto candidates = (r.max.x - r.min.x + 1) * (r.max.y - r.min.y + 1);
  for (int y = r.min.y; y <= r.max.y; ++y) {
    for (int x = r.min.x; x <= r.max.x; ++x) d.fill({x, y}, dc::light_gray);
  }
  tri::ch08::SpanWalker walker(*setup);
  int spanned = 0;
  for (int y = walker.first_row(); y <= walker.last_row(); ++y, walker.next_row()) {
    const tri::ch08::RowSpan s = walker.span();
    for (int x = s.first; x <= s.last; ++x) {
      d.fill({x, y}, y % 2 == 0 ? dc::sky_blue : dc::orange);
      ++spanned;
    }
  }
  outline(d, r, dc::dark_gray, 2, true);
  draw_triangle(d, t, {LabelPlace::below_right, LabelPlace::left, LabelPlace::above_left});
  d.legend_fill("candidate pixel: tested by steps 1 and 2", dc::light_gray);
  d.legend_fill("span, even row", dc::sky_blue);
  d.legend_fill("span, odd row", dc::orange);
  d.legend_line("ideal triangle", dc::black);
  d.legend_line("candidate pixels", dc::dark_gray, true);
  d.legend_note("Steps 1 and 2 test " + std::to_string(candidates) + " pixels; the spans fill " +
                std::to_string(spanned) + ", testing none.");
  return d.svg();
}

// Step 4: the 8x8 blocks of a triangle's candidate pixels by class; a partial block's pixels by
// whether they are covered.
std::string blocks_figure() {
  const Triangle t{{{3.25, 2.5}, {69.5, 14.75}, {23.5, 51.25}}};
  const auto setup = tri::ch08::setup_triangle(t, 72, 56);
  PixelDiagram d({0, 0}, {71, 55}, "8x8 blocks: skipped, filled without a test, or tested", 10);
  int inside = 0, outside = 0, partial = 0;
  std::vector<PixelBox> blocks, empty_blocks;
  tri::ch08::for_each_block(*setup, [&](const PixelBox& block, tri::ch08::BlockCoverage c) {
    blocks.push_back(block);
    bool any = false;
    for (int y = block.min.y; y <= block.max.y; ++y) {
      for (int x = block.min.x; x <= block.max.x; ++x) {
        const bool covered = setup->covers(x, y);
        any = any || covered;
        switch (c) {
          case tri::ch08::BlockCoverage::inside:
            d.fill({x, y}, light_green);
            break;
          case tri::ch08::BlockCoverage::outside:
            d.fill({x, y}, dc::light_gray);
            break;
          case tri::ch08::BlockCoverage::partial:
            d.fill({x, y}, covered ? dc::sky_blue : light_orange);
            break;
        }
      }
    }
    inside += c == tri::ch08::BlockCoverage::inside;
    outside += c == tri::ch08::BlockCoverage::outside;
    partial += c == tri::ch08::BlockCoverage::partial;
    if (c == tri::ch08::BlockCoverage::partial && !any) empty_blocks.push_back(block);
  });
  for (const auto& block : blocks) outline(d, block, dc::black, 2);
  for (const auto& block : empty_blocks) outline(d, block, dc::vermillion, 4);
  draw_triangle(d, t, {LabelPlace::below_right, LabelPlace::above_left, LabelPlace::right});
  d.legend_fill("inside block: filled without a test", light_green);
  d.legend_fill("outside block: skipped", dc::light_gray);
  d.legend_fill("partial block, pixel covered", dc::sky_blue);
  d.legend_fill("partial block, pixel not covered", light_orange);
  d.legend_line("ideal triangle", dc::black);
  d.legend_line("partial, yet no pixel covered: no single edge rejects it", dc::vermillion);
  d.legend_note(std::to_string(inside) + " inside, " + std::to_string(outside) + " outside, " +
                std::to_string(partial) + " partial blocks, " +
                std::to_string(empty_blocks.size()) + " of them without a covered pixel.");
  return d.svg();
}

// Step 5: a triangle within one block, tested one row of eight lanes at a time: each lane's sign
// from lane_test, the code draw_triangle_simd runs; the lanes past the candidate pixels stay off.
std::string simd_lanes_figure() {
  const Triangle t{{{1.25, 0.5}, {6.75, 2.25}, {2.5, 5.75}}};
  const auto setup = tri::ch08::setup_triangle(t, 10, 7);
  PixelDiagram d({0, 0}, {9, 6}, "Step 5: each row of the block is one vector of 8 lanes", 48);
  const auto& r = setup->range;
  d.show_centres(false);  // each cell shows its lane number instead
  for (int y = r.min.y; y <= r.max.y; ++y) {
    const auto lanes = tri::ch08::lane_test(*setup, r.min.x, y, tri::ch08::LaneWidth::bits32, 8);
    for (int i = 0; i < 8; ++i) {
      const glm::ivec2 pixel{r.min.x + i, y};
      const bool past_range = pixel.x > r.max.x;
      d.fill(pixel, lanes[static_cast<std::size_t>(i)] ? dc::sky_blue
                    : past_range                       ? dc::light_gray
                                                       : light_orange);
      d.pixel_text(pixel, std::to_string(i));
      if (past_range) d.mark(pixel, PixelMark::hatch, dc::dark_gray);
    }
    d.frame({r.min.x, y}, {r.min.x + 7, y}, dc::black, 1.5);
  }
  outline(d, r, dc::dark_gray, 2.5, true);
  draw_triangle(d, t, {LabelPlace::below_right, LabelPlace::right, LabelPlace::above_left});
  d.legend_fill("lane >= 0: the blend stores the triangle's colour", dc::sky_blue);
  d.legend_fill("lane < 0 (an edge fails): the blend keeps the old pixel", light_orange);
  d.legend_mark("lane past the candidate pixels: its fourth term is < 0", PixelMark::hatch,
                dc::dark_gray);
  d.legend_line("one vector: pixels x .. x + 7 of a row, the number is the lane", dc::black);
  d.legend_line("candidate pixels", dc::dark_gray, true);
  d.legend_line("ideal triangle", dc::black);
  return d.svg();
}

// Step 6: mixed triangles by the path the hybrid takes: lanes for a triangle whose candidate
// pixels fit in one 8x8 block, spans for the rest.
std::string hybrid_paths_figure() {
  Canvas canvas(160, 120);
  tri::Random random(8);
  std::vector<Triangle> triangles;
  int lanes = 0, spans = 0;
  for (int i = 0; i < 140; ++i) {
    const double extent = i % 3 == 0 ? random.real(8, 30) : random.real(1, 4);
    // y before x, one draw a statement: the order the figure was first drawn in, on every compiler.
    const double centre_y = random.real(0, 120);
    const double centre_x = random.real(0, 160);
    const glm::dvec2 centre(centre_x, centre_y);
    const Triangle t = triangle_around(random, centre, extent);
    const auto setup = tri::ch08::setup_triangle(t, 160, 120);
    if (!setup) continue;
    const bool one_block = tri::ch08::fits_one_block(*setup);
    (one_block ? lanes : spans) += 1;
    tri::ch08::draw_triangle_spans(canvas, t, one_block ? dc::purple : dc::sky_blue);
    triangles.push_back(t);
  }
  PixelDiagram d({0, 0}, {159, 119}, "The hybrid's path per triangle: lanes or spans", 4);
  d.show_centres(false);
  d.fill_from(canvas, tri::colors::black);
  for (const auto& t : triangles) edges(d, t, 0.75);
  d.legend_fill("fits one 8x8 block: lane test (" + std::to_string(lanes) + " triangles)",
                dc::purple);
  d.legend_fill("larger: spans (" + std::to_string(spans) + " triangles)", dc::sky_blue);
  d.legend_line("ideal triangle edges", dc::black);
  d.legend_note("Where triangles overlap, the later one is on top (scene order).");
  return d.svg();
}

// Step 6, close up: the two paths on one small and one larger triangle. The small one's candidate
// pixels fit one 8x8 block, and every one of them is tested in lanes; the larger one is drawn as
// spans, which touch only the covered pixels.
std::string hybrid_paths_zoom_figure() {
  const Triangle small{{{1.5, 2.25}, {7.25, 4.5}, {3.75, 8.5}}};
  const Triangle large{{{10.5, 1.25}, {22.5, 4.75}, {14.25, 10.5}}};
  const glm::ivec2 first(0, 0), last(23, 11);
  PixelDiagram d(first, last,
                 "Close up: lanes test every candidate pixel, spans touch only covered ones", 26);
  const auto small_setup = tri::ch08::setup_triangle(small, 24, 12);
  const auto& r = small_setup->range;
  for (int y = r.min.y; y <= r.max.y; ++y) {
    for (int x = r.min.x; x <= r.max.x; ++x) {
      d.fill({x, y}, small_setup->covers(x, y) ? dc::purple : light_purple);
    }
  }
  outline(d, r, dc::dark_gray, 2, true);
  const auto large_setup = tri::ch08::setup_triangle(large, 24, 12);
  tri::ch08::SpanWalker walker(*large_setup);
  for (int y = walker.first_row(); y <= walker.last_row(); ++y, walker.next_row()) {
    const tri::ch08::RowSpan s = walker.span();
    for (int x = s.first; x <= s.last; ++x) d.fill({x, y}, dc::sky_blue);
  }
  outline(d, large_setup->range, dc::dark_gray, 2, true);
  d.triangle(small[0], small[1], small[2], dc::black);
  d.triangle(large[0], large[1], large[2], dc::black);
  d.vertex(small[0], "A", LabelPlace::below_right);
  d.vertex(small[1], "B", LabelPlace::below_right);
  d.vertex(small[2], "C", LabelPlace::above_right);
  d.vertex(large[0], "A", LabelPlace::below_right);
  d.vertex(large[1], "B", LabelPlace::below_left);
  d.vertex(large[2], "C", LabelPlace::above_right);
  d.legend_fill("lanes: tested, covered", dc::purple);
  d.legend_fill("lanes: tested, not covered", light_purple);
  d.legend_fill("spans: filled without a test", dc::sky_blue);
  d.legend_line("candidate pixels", dc::dark_gray, true);
  d.legend_line("ideal triangles", dc::black);
  d.legend_note(
      "Left: candidate pixels within one 8x8 block (fits_one_block). Right: larger, so "
      "spans; the rest of its frame is never touched.");
  return d.svg();
}

// Step 7: a scene drawn by two threads; every row tinted by the thread that owns its band. Each
// thread draws every triangle, clipped to its bands; the result is the serial picture whatever
// the timing, so the figure is the same on every run.
std::string bands_figure() {
  const Color background{30, 30, 30, 255};
  Canvas canvas(128, 96, background);
  tri::Random random(3);
  std::vector<tri::SceneTriangle> scene;
  for (int i = 0; i < 24; ++i) {
    // y before x, one draw a statement: the order the figure was first drawn in, on every compiler.
    const double centre_y = random.real(0, 96);
    const double centre_x = random.real(0, 128);
    const glm::dvec2 centre(centre_x, centre_y);
    const double extent = random.real(10, 40);
    const Triangle t = triangle_around(random, centre, extent);
    const auto level = static_cast<std::uint8_t>(random.integer(120, 255));
    scene.push_back({t, Color{level, level, level, 255}});
  }
  tri::ch08::draw_batch_on_threads(canvas, scene, 2);
  const auto bands = tri::ch08::bands_for(canvas.height(), 2);
  const std::array<Color, 2> tints{dc::blue, dc::orange};
  PixelDiagram d({0, 0}, {127, 95},
                 "Two threads, bands of " + std::to_string(bands.rows) + " rows dealt in turn", 5);
  d.show_centres(false);
  for (int y = 0; y < canvas.height(); ++y) {
    const Color tint = tints[static_cast<std::size_t>(bands.owner(y))];
    for (int x = 0; x < canvas.width(); ++x) {
      const Color c = canvas.pixel(x, y);
      // Empty pixels show the owner's colour faintly; drawn ones its colour over the grey.
      d.fill({x, y}, c == background ? mix(tint, dc::empty, 80) : mix(c, tint, 55));
    }
  }
  for (int y = bands.rows; y < canvas.height(); y += bands.rows) {
    d.line({-0.5, y - 0.5}, {127.5, y - 0.5}, dc::black, 1.5);
  }
  for (const auto& t : scene) edges(d, t.vertices, 0.75);
  d.legend_fill("empty, row of thread 0", mix(tints[0], dc::empty, 80));
  d.legend_fill("drawn by thread 0", mix(Color{190, 190, 190, 255}, tints[0], 55));
  d.legend_fill("empty, row of thread 1", mix(tints[1], dc::empty, 80));
  d.legend_fill("drawn by thread 1", mix(Color{190, 190, 190, 255}, tints[1], 55));
  d.legend_line("band border", dc::black);
  d.legend_note(
      "Triangles are drawn in grey levels 120 to 255 under the tint; thin lines: "
      "their ideal edges.");
  return d.svg();
}

// Step 8: the bytes one row of 16 pixels takes in each format, one cell per byte: RGBA8 (4 bytes
// a pixel), a palette index (1 byte) and a mask (1 bit: 8 pixels a byte).
std::string bytes_per_pixel_figure() {
  constexpr int pixels = 16;
  constexpr int rgba_bytes = static_cast<int>(sizeof(Color));
  PixelDiagram d({0, 0}, {pixels * rgba_bytes - 1, 4},
                 "The same 16 pixels: 4 bytes each, 1 byte each, 1 bit each", 18);
  d.show_centres(false);
  const std::array<Color, 2> alternate{dc::sky_blue, light_blue};
  const std::array<const char*, 4> channels{"R", "G", "B", "A"};
  for (int p = 0; p < pixels; ++p) {
    const Color c = alternate[static_cast<std::size_t>(p % 2)];
    for (int b = 0; b < rgba_bytes; ++b) {
      d.fill({p * rgba_bytes + b, 4}, c);
      d.pixel_text({p * rgba_bytes + b, 4}, channels[static_cast<std::size_t>(b)]);
    }
    d.fill({p, 2}, p % 2 == 0 ? dc::orange : light_orange);
    d.pixel_text({p, 2}, std::to_string(p));
  }
  for (int byte = 0; byte < pixels / 8; ++byte) {
    d.fill({byte, 0}, byte % 2 == 0 ? dc::purple : light_purple);
  }
  d.legend_fill(
      "RGBA8 (row 4): " + std::to_string(pixels * rgba_bytes) + " bytes, one pixel = R, G, B, A",
      dc::sky_blue);
  d.legend_fill("palette index (row 2): " + std::to_string(pixels) + " bytes, one per pixel",
                dc::orange);
  d.legend_fill("mask (row 0): " + std::to_string(pixels / 8) +
                    " bytes, pixels 0-7 in the first, 8-15 in the second",
                dc::purple);
  d.legend_note("Each cell is one byte; the write ceiling limits bytes, not pixels.");
  return d.svg();
}

// Step 9: a scene binned into the tiles of its canvas: each triangle by whether it lies in one
// tile (listed by index) or over several (set up once, listed in each), each tile with its count.
std::string tiles_figure() {
  constexpr int width = 160, height = 120;
  const Color background{255, 255, 255, 255};
  Canvas canvas(width, height, background);
  tri::Random random(9);
  std::vector<tri::SceneTriangle> scene;
  for (int i = 0; i < 40; ++i) {
    const double extent = i % 4 == 0 ? random.real(15, 40) : random.real(2, 6);
    // y before x, one draw a statement: the order the figure was first drawn in, on every compiler.
    const double centre_y = random.real(0, height);
    const double centre_x = random.real(0, width);
    const glm::dvec2 centre(centre_x, centre_y);
    const Triangle t = triangle_around(random, centre, extent);
    scene.push_back({t, tri::colors::black});
  }
  tri::ch08::TileBins bins;
  bins.start(scene, width, height);
  for (int chunk = 0; chunk < bins.chunks(); ++chunk) bins.bin_chunk(chunk);
  const tri::ch08::TileGrid& grid = bins.grid();
  std::vector<int> tiles_of(scene.size(), 0);
  for (int tile = 0; tile < grid.count(); ++tile) {
    for (const std::uint32_t i : bins.triangles_of(tile)) ++tiles_of[i];
  }
  int one = 0, several = 0;
  for (std::size_t i = 0; i < scene.size(); ++i) {
    if (tiles_of[i] == 0) continue;
    (tiles_of[i] == 1 ? one : several) += 1;
    tri::ch08::draw_triangle_spans(canvas, scene[i].vertices,
                                   tiles_of[i] == 1 ? dc::purple : dc::sky_blue);
  }
  PixelDiagram d({0, 0}, {width - 1, height - 1},
                 "Binning: " + std::to_string(grid.count()) + " tiles of " +
                     std::to_string(grid.tile_width()) + "x" + std::to_string(grid.tile_height()) +
                     " pixels, cut by the canvas",
                 4);
  d.show_centres(false);
  d.fill_from(canvas, background);
  for (const auto& t : scene) edges(d, t.vertices, 0.75);
  for (int tile = 0; tile < grid.count(); ++tile) {
    const PixelBox box = grid.tile(tile, width, height);
    outline(d, box, dc::vermillion, 2);
    d.label({box.max.x - 0.5, (box.min.y + box.max.y) / 2.0},
            "tile " + std::to_string(tile) + ": " + std::to_string(bins.triangles_of(tile).size()) +
                " listed",
            LabelPlace::left);
  }
  d.legend_fill("in one tile: listed by index (" + std::to_string(one) + " triangles)", dc::purple);
  d.legend_fill(
      "over several tiles: set up once, listed in each (" + std::to_string(several) + " triangles)",
      dc::sky_blue);
  d.legend_line("tile border", dc::vermillion);
  d.legend_line("ideal triangle edges", dc::black);
  d.legend_note("Tiles are 512 pixels wide: on this 160-pixel canvas each tile is a band of rows.");
  return d.svg();
}

// Step 10: eight small triangles set up together, one per lane, each field an array over the
// lanes; with AVX2 one instruction holds four lanes, so lanes 0-3 and 4-7 are two passes.
std::string setup_lanes_figure() {
  constexpr int width = 64, height = 12;
  tri::Random random(10);
  std::vector<tri::SceneTriangle> scene;
  for (int lane = 0; lane < tri::ch08::setup_lanes; ++lane) {
    const glm::dvec2 centre(4 + 8 * lane, 5.5);
    const Triangle t = triangle_around(random, centre, 3.5);
    scene.push_back({t, tri::colors::black});
  }
  tri::ch08::SetupLanes lanes;
  tri::ch08::set_up_lanes(scene, width, height, lanes, tri::ch08::InstructionSet::portable);
  PixelDiagram d({0, 0}, {width - 1, height - 1},
                 "Eight triangles set up at once: one lane each, fields as arrays of eight", 14);
  const std::array<Color, 2> pass_colors{dc::sky_blue, dc::orange};
  const std::array<Color, 2> pass_light{light_blue, light_orange};
  for (int lane = 0; lane < tri::ch08::setup_lanes; ++lane) {
    const auto i = static_cast<std::size_t>(lane);
    const std::size_t pass = i / 4;
    if (lanes.result[i] == tri::ch08::LaneResult::set_up) {
      const tri::ch08::TriangleSetup setup = lanes.setup(lane);
      const PixelBox& r = setup.range;
      for (int y = r.min.y; y <= r.max.y; ++y) {
        for (int x = r.min.x; x <= r.max.x; ++x) {
          d.fill({x, y}, setup.covers(x, y) ? pass_colors[pass] : pass_light[pass]);
        }
      }
      outline(d, r, dc::dark_gray, 1.5, true);
    }
    edges(d, scene[i].vertices, 1.5);
    d.label({4.0 + 8 * lane, 10.5}, "lane " + std::to_string(lane), LabelPlace::above_right);
  }
  d.legend_fill("lanes 0-3, covered: the first AVX2 pass (4 doubles per instruction)",
                dc::sky_blue);
  d.legend_fill("lanes 4-7, covered: the second pass", dc::orange);
  d.legend_fill("candidate pixel, not covered (lanes 0-3)", light_blue);
  d.legend_fill("candidate pixel, not covered (lanes 4-7)", light_orange);
  d.legend_line("candidate pixels of a lane (its min/max fields)", dc::dark_gray, true);
  d.legend_line("ideal triangle", dc::black);
  d.legend_note(
      "Every field (snapped vertices, edge values and steps, candidate box) is an array of 8; "
      "then each lane goes to fill_hybrid in order.");
  return d.svg();
}

}  // namespace

int main(int argc, char** argv) {
  return tri::run_chapter_program(
      argc, argv, "08_fast_exact",
      "Chapter 08, fast and still exact: one edge's value pixel by pixel\n"
      "(08_incremental_values.svg), which edges each pixel passes (08_edge_signs.svg), the spans\n"
      "of a sliver in its bounding box (08_sliver_spans.svg), a triangle's 8x8 blocks by class\n"
      "(08_blocks.svg), a row's eight lanes (08_simd_lanes.svg), the path the hybrid takes per\n"
      "triangle (08_hybrid_paths.svg, close up in 08_hybrid_paths_zoom.svg), the bands two\n"
      "threads share (08_bands.svg), the bytes of each pixel format (08_bytes_per_pixel.svg), a\n"
      "scene binned into tiles (08_tiles.svg) and eight triangles set up in lanes\n"
      "(08_setup_lanes.svg).",
      [](tri::FigureWriter& figures) {
        figures.save_svg("08_incremental_values", incremental_values_figure());
        figures.save_svg("08_edge_signs", edge_signs_figure());
        figures.save_svg("08_simd_lanes", simd_lanes_figure());
        figures.save_svg("08_sliver_spans", sliver_spans_figure());
        figures.save_svg("08_blocks", blocks_figure());
        figures.save_svg("08_hybrid_paths", hybrid_paths_figure());
        figures.save_svg("08_hybrid_paths_zoom", hybrid_paths_zoom_figure());
        figures.save_svg("08_bands", bands_figure());
        figures.save_svg("08_bytes_per_pixel", bytes_per_pixel_figure());
        figures.save_svg("08_tiles", tiles_figure());
        figures.save_svg("08_setup_lanes", setup_lanes_figure());
      });
}
