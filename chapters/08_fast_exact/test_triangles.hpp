/// @file
/// Seeded triangles on the 1/256 grid for chapter 08's tests (tests only): every size from
/// sub-pixel to canvas-covering, slivers, vertices far off the canvas, and pixel-grid ties.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "chapters/07_exact_coverage/coverage_oracle.hpp"
#include "chapters/08_fast_exact/narrow_canvases.hpp"
#include "chapters/08_fast_exact/triangle_setup.hpp"
#include "common/canvas.hpp"
#include "common/scene.hpp"
#include "common/triangle_algorithm.hpp"
#include "tests/support/pixels.hpp"

namespace tri::ch08::testing {

/// A coordinate on the 1/256 grid in [low, high).
inline double grid_coordinate(tri::testing::Random& random, double low, double high) {
  return std::floor(random.real(low, high) * 256) / 256;
}

/// The kinds of triangle the exactness tests cycle through.
enum class Shape { tiny, small, medium, large, sliver, integer, far, huge, count };

/// A triangle of the given shape near a size x size canvas (partly off it at times), with
/// vertices on the 1/256 grid.
inline Triangle random_triangle(tri::testing::Random& random, Shape shape, int size) {
  const double cx = random.real(-4, size + 4), cy = random.real(-4, size + 4);
  const auto around = [&](double extent) {
    Triangle t;
    for (auto& v : t) {
      v = {grid_coordinate(random, cx - extent, cx + extent),
           grid_coordinate(random, cy - extent, cy + extent)};
    }
    return t;
  };
  switch (shape) {
    case Shape::tiny:
      return around(1.5);
    case Shape::small:
      return around(5);
    case Shape::medium:
      return around(20);
    case Shape::large:
      return around(2.0 * size);
    case Shape::sliver: {
      // Two far-apart vertices and a third within half a pixel of their line.
      const Triangle t = around(size);
      const double s = random.real(0.2, 0.8);
      const glm::dvec2 on_line = t[0] + s * (t[1] - t[0]);
      return {t[0],
              t[1],
              {std::round((on_line.x + random.real(-0.5, 0.5)) * 256) / 256,
               std::round((on_line.y + random.real(-0.5, 0.5)) * 256) / 256}};
    }
    case Shape::integer: {
      // Vertices on pixel centres: many edges pass exactly through centres (top-left ties).
      Triangle t;
      for (auto& v : t) {
        v = {std::round(cx + random.real(-12, 12)), std::round(cy + random.real(-12, 12))};
      }
      return t;
    }
    case Shape::far: {
      // Two vertices up to 2^21 pixels away: still within chapter 07's 64-bit budget or just out.
      Triangle t = around(6);
      t[1] = {std::round(random.real(-2097152.0, 2097152.0)), t[1].y};
      t[2] = {t[2].x, std::round(random.real(-2097152.0, 2097152.0))};
      return t;
    }
    case Shape::huge: {
      // Vertices anywhere within ±2^30: the 128-bit setup and its clamped edges.
      Triangle t;
      for (auto& v : t) {
        v = {std::round(random.real(-1073741824.0, 1073741824.0)),
             std::round(random.real(-1073741824.0, 1073741824.0))};
      }
      if (random.integer(0, 1) == 0) {
        t[0] = {grid_coordinate(random, 0, size), grid_coordinate(random, 0, size)};
      }
      return t;
    }
    case Shape::count:
      break;
  }
  return around(1);
}

/// The i-th shape of the cycle.
inline Shape shape_number(int i) {
  return static_cast<Shape>(i % static_cast<int>(Shape::count));
}

/// Calls visit(i, setup) for the first `count` triangles of the shape cycle that have candidate
/// pixels on a width x height canvas (the i-th triangle has shape_number(i)).
template <class Visit>
void for_each_random_setup(tri::testing::Random& random, int count, int width, int height,
                           Visit&& visit) {
  for (int i = 0; i < count; ++i) {
    const auto setup =
        setup_triangle(random_triangle(random, shape_number(i), width), width, height);
    if (setup) visit(i, *setup);
  }
}

/// `count` overlapping triangles of every shape near a size x size canvas, in many colours: a
/// later one paints over earlier ones, so any change of order shows in the colours.
inline std::vector<SceneTriangle> overlapping_scene(std::uint64_t seed, int count, int size) {
  tri::testing::Random random(seed);
  std::vector<SceneTriangle> scene;
  for (int i = 0; i < count; ++i) {
    scene.push_back({random_triangle(random, shape_number(i), size),
                     Color{static_cast<std::uint8_t>(random.integer(0, 255)),
                           static_cast<std::uint8_t>(random.integer(0, 255)),
                           static_cast<std::uint8_t>(i % 256), 255}});
  }
  return scene;
}

/// A fresh width x height canvas, counting writes when asked, after draw(canvas).
template <class Draw>
Canvas drawn_on(int width, int height, bool counting, Draw&& draw) {
  Canvas canvas(width, height);
  if (counting) canvas.enable_write_counts();
  draw(canvas);
  return canvas;
}

/// Whether two canvases hold the same colours and the same write counts.
inline bool same_canvas(const Canvas& a, const Canvas& b) {
  return std::equal(a.pixels().begin(), a.pixels().end(), b.pixels().begin(), b.pixels().end()) &&
         std::equal(a.write_counts().begin(), a.write_counts().end(), b.write_counts().begin(),
                    b.write_counts().end());
}

/// How many pixels of the index8 and mask1 canvases a narrow draw leaves differ from the oracle's
/// drawing of the same (valid) triangles, triangle i in palette entry i % 255 + 1, later over
/// earlier; `drawn` adds the covered pixels, so a caller can see the comparison is not empty.
inline int narrow_pixels_off_oracle(DrawNarrowFunction draw,
                                    std::span<const SceneTriangle> triangles, int width, int height,
                                    int& drawn) {
  constexpr Color background{0, 0, 0, 0};
  const auto color_of = [](std::uint8_t index) { return Color{index, 1, 2, 255}; };
  std::vector<std::uint8_t> index_of;
  Canvas truth(width, height, background);
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    index_of.push_back(static_cast<std::uint8_t>(i % 255 + 1));
    tri::ch07::draw_triangle_oracle(truth, triangles[i].vertices, color_of(index_of.back()));
  }
  IndexCanvas indices(width, height);
  MaskCanvas mask(width, height);
  NarrowTarget index8{.indices = &indices, .index_of = index_of};
  NarrowTarget mask1{.mask = &mask};
  draw(index8, triangles);
  draw(mask1, triangles);
  int off = 0;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const Color want = truth.pixel(x, y);
      const std::uint8_t index = indices.index(x, y);
      off += (index == 0 ? background : color_of(index)) != want;
      off += mask.covered(x, y) != (want != background);
      drawn += want != background;
    }
  }
  return off;
}

}  // namespace tri::ch08::testing
