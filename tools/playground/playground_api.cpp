/// @file
/// The playground's C++ side, compiled to WebAssembly by em++ only
/// (tools/playground/CMakeLists.txt): the registry's list of algorithms; two triangles drawn with a
/// registered triangle algorithm and with chapter 07's oracle, as per-pixel write counts; and two
/// triangles' coverage by a coverage algorithm (rule area) and by chapter 09's exact area, as
/// raster --coverage writes it. Every pixel value is the chapters' code; the page's JavaScript only
/// draws the results and handles input. The functions keep no state: the page owns every buffer and
/// passes it in.
#include <emscripten/emscripten.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "chapters/03_interpolate_fill/fill_steps.hpp"
#include "chapters/04_scanline/lower_half.hpp"
#include "chapters/04_scanline/outline_steps.hpp"
#include "chapters/04_scanline/scanline_fills.hpp"
#include "chapters/07_exact_coverage/coverage_oracle.hpp"
#include "chapters/09_anti_aliasing/area_oracle.hpp"
#include "chapters/09_anti_aliasing/coverage_canvas.hpp"
#include "common/canvas.hpp"
#include "common/scene.hpp"
#include "common/triangle_algorithm.hpp"
#include "measure/registry.hpp"

namespace {

// The largest grid the page offers: big enough for the chapters' cases, small enough that the
// slowest algorithm redraws it at once while a vertex is dragged.
constexpr int max_width = 64;
constexpr int max_height = 48;

// The two triangles' colours, so that the last writer of a pixel can be read back.
constexpr std::array<tri::Color, 2> triangle_colors{tri::Color{230, 159, 0, 255},
                                                    tri::Color{86, 180, 233, 255}};

// Copies text into a buffer of `capacity` bytes, cut if need be and always ended by a zero.
void copy_text(std::string_view text, char* out, std::size_t capacity) {
  if (out == nullptr || capacity == 0) return;
  const std::size_t n = std::min(text.size(), capacity - 1);
  std::copy_n(text.data(), n, out);
  out[n] = '\0';
}

// Draws the triangles into a counting canvas the way `raster --counts` does (draw_triangles: one
// batch, so batch algorithms see both), and copies out each pixel's write count and which
// triangle wrote it last (1 or 2, 0 for none), bottom row first.
void draw_counted(const tri::TriangleAlgorithm& algorithm, int width, int height,
                  std::span<const tri::SceneTriangle> triangles, std::uint32_t* counts,
                  std::uint8_t* last_writer, std::uint32_t* outside_writes) {
  tri::Canvas canvas(width, height);
  canvas.enable_write_counts();
  tri::draw_triangles(algorithm, canvas, triangles);
  const auto written = canvas.write_counts();
  std::copy(written.begin(), written.end(), counts);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const tri::Color c = canvas.pixel(x, y);
      const auto i = tri::pixel_index(x, y, width);
      last_writer[i] = c == triangle_colors[0] ? 1 : c == triangle_colors[1] ? 2 : 0;
    }
  }
  *outside_writes =
      static_cast<std::uint32_t>(std::min<std::uint64_t>(canvas.outside_writes(), UINT32_MAX));
}

// The grid check both drawing functions make first.
bool grid_fits(int width, int height, char* message, std::size_t capacity) {
  if (width >= 1 && width <= max_width && height >= 1 && height <= max_height) return true;
  copy_text("the grid must be 1 to 64 pixels wide and 1 to 48 high", message, capacity);
  return false;
}

// The two triangles of `vertices` (x0 y0 x1 y1 x2 y2 of each), in the colours above.
std::array<tri::SceneTriangle, 2> two_triangles(const double* vertices) {
  std::array<tri::SceneTriangle, 2> triangles;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    for (std::size_t v = 0; v < 3; ++v) {
      triangles[t].vertices[v] = {vertices[6 * t + 2 * v], vertices[6 * t + 2 * v + 1]};
    }
    triangles[t].color = triangle_colors[t];
  }
  return triangles;
}

// raster writes no file when a triangle is refused; the page likewise draws nothing. True when
// the library accepts both triangles; otherwise the message says which and why.
bool library_accepts(const std::array<tri::SceneTriangle, 2>& triangles, char* message,
                     std::size_t capacity) {
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const tri::DrawResult result = tri::validate_triangle(triangles[t].vertices);
    if (result != tri::DrawResult::drawn) {
      copy_text(std::string(t == 0 ? "triangle 1: " : "triangle 2: ") +
                    std::string(tri::describe(result)),
                message, capacity);
      return false;
    }
  }
  return true;
}

// A double as JSON: the shortest "%.17g" that reads back as the same value.
std::string json_number(double value) {
  std::array<char, 32> text{};
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(text.data(), text.size(), "%.*g", digits, value);
    if (std::strtod(text.data(), nullptr) == value) break;
  }
  return text.data();
}

// {"first": row, "values": [...]}: one array of chapter 03 with the row of its first value.
std::string json_rows(int first_row, const std::vector<double>& values) {
  std::string text = "{\"first\":" + std::to_string(first_row) + ",\"values\":[";
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) text += ",";
    text += json_number(values[i]);
  }
  return text + "]}";
}

// The grid check, then the two triangles when the library accepts both: what every drawing
// function starts with. Otherwise the message says why and nothing is returned.
std::optional<std::array<tri::SceneTriangle, 2>> accepted_triangles(int width, int height,
                                                                    const double* vertices,
                                                                    char* message,
                                                                    std::size_t capacity) {
  if (!grid_fits(width, height, message, capacity)) return std::nullopt;
  const auto triangles = two_triangles(vertices);
  if (!library_accepts(triangles, message, capacity)) return std::nullopt;
  return triangles;
}

// The first triangle's vertices rounded to their nearest pixel centres, as the registry hands
// them to the articles' fills (draw_at_nearest_pixels), when the grid fits and the library
// accepts both triangles.
std::optional<std::array<glm::ivec2, 3>> first_triangle_pixels(int width, int height,
                                                               const double* vertices) {
  std::array<char, 8> unused{};
  const auto triangles = accepted_triangles(width, height, vertices, unused.data(), unused.size());
  if (!triangles) return std::nullopt;
  const auto& v = (*triangles)[0].vertices;
  return std::array<glm::ivec2, 3>{tri::nearest_pixel(v[0]), tri::nearest_pixel(v[1]),
                                   tri::nearest_pixel(v[2])};
}

}  // namespace

extern "C" {

/// Writes the registered algorithms, one a line: name, chapter, rule, 1 when threaded (else 0)
/// and summary, tab-separated, in the registry's order: the triangle algorithms, then the
/// coverage ones (rule area). Returns the text's length; it is written only when it fits in
/// `capacity` bytes with its final zero.
EMSCRIPTEN_KEEPALIVE std::size_t playground_algorithms(char* out, std::size_t capacity) {
  std::string text;
  for (const tri::Drawable& a : tri::registered_drawables()) {
    text.append(a.name).append("\t").append(a.chapter).append("\t");
    text.append(tri::rule_name(a.rule)).append(a.threaded ? "\t1\t" : "\t0\t");
    text.append(a.summary).append("\n");
  }
  if (text.size() < capacity) copy_text(text, out, capacity);
  return text.size();
}

/// Draws two triangles (`vertices`: x0 y0 x1 y1 x2 y2 of the first, then of the second, in
/// pixel units, y up, integers on pixel centres) on a width x height canvas with the registered
/// algorithm `name`, and with chapter 07's oracle. Fills, for each of the two, width x height
/// write counts and last writers (bottom row first) and its count of writes off the canvas.
/// Returns 0 when both were drawn. Otherwise draws nothing, writes why into `message` and
/// returns 1 for a triangle the library refuses (NaN, infinite, beyond ±2^30: the message is
/// the library's), 2 for an unknown or non-triangle algorithm, 3 for a grid out of bounds.
EMSCRIPTEN_KEEPALIVE int playground_draw(const char* name, int width, int height,
                                         const double* vertices, std::uint32_t* counts,
                                         std::uint8_t* last_writer, std::uint32_t* oracle_counts,
                                         std::uint8_t* oracle_last_writer,
                                         std::uint32_t* outside_writes, char* message,
                                         std::size_t message_capacity) {
  const auto drawables = tri::registered_drawables();
  const tri::Drawable* drawable = tri::find_named(drawables, name);
  const tri::TriangleAlgorithm* algorithm = drawable != nullptr ? drawable->colours : nullptr;
  if (algorithm == nullptr) {
    copy_text(std::string("no triangle algorithm '") + name + "'", message, message_capacity);
    return 2;
  }
  const auto triangles = accepted_triangles(width, height, vertices, message, message_capacity);
  if (!triangles) return 1;
  const tri::TriangleAlgorithm oracle{.name = "oracle",
                                      .chapter = "07_exact_coverage",
                                      .rule = tri::CoverageRule::top_left,
                                      .summary = "chapter 07's oracle",
                                      .draw = tri::ch07::draw_triangle_oracle};
  draw_counted(*algorithm, width, height, *triangles, counts, last_writer, &outside_writes[0]);
  draw_counted(oracle, width, height, *triangles, oracle_counts, oracle_last_writer,
               &outside_writes[1]);
  copy_text("", message, message_capacity);
  return 0;
}

/// The coverage of the same two triangles (as playground_draw takes them) by the registered
/// coverage algorithm `name` (rule area), summed, and their exact coverage by chapter 09's oracle,
/// summed: each pixel as the 16-bit value raster --coverage writes, round(65535 x c) with c
/// clamped to [0, 1] (bottom row first). Returns 0 when drawn. Otherwise draws nothing, writes
/// why into `message` and returns 1 for a triangle the library refuses or that is off the exact
/// area's grid (1/256 pixel, within ±2^15: the library's message), 2 for an unknown algorithm, 3
/// for a grid out of bounds.
EMSCRIPTEN_KEEPALIVE int playground_coverage(const char* name, int width, int height,
                                             const double* vertices, std::uint16_t* coverage,
                                             std::uint16_t* exact, char* message,
                                             std::size_t message_capacity) {
  const auto drawables = tri::registered_drawables();
  const tri::Drawable* drawable = tri::find_named(drawables, name);
  const tri::ch09::AreaAlgorithm* algorithm = drawable != nullptr ? drawable->coverage : nullptr;
  if (algorithm == nullptr) {
    copy_text(std::string("no coverage algorithm '") + name + "'", message, message_capacity);
    return 2;
  }
  const auto accepted = accepted_triangles(width, height, vertices, message, message_capacity);
  if (!accepted) return 1;
  const auto& triangles = *accepted;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    try {
      tri::ch09::require_on_oracle_grid(triangles[t].vertices);
    } catch (const std::invalid_argument& error) {
      copy_text(std::string(t == 0 ? "triangle 1: " : "triangle 2: ") + error.what(), message,
                message_capacity);
      return 1;
    }
  }
  try {
    tri::ch09::CoverageCanvas canvas(width, height);
    tri::ch09::draw_coverage(*algorithm, canvas, triangles);
    // The truth pixel by pixel over the grid only, so a triangle far larger than the grid costs
    // no more than the grid (measure/area_error.cpp sums the same way, in doubles).
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        double sum = 0;
        for (const auto& triangle : triangles) {
          sum += tri::ch09::exact_coverage(triangle.vertices, {x, y}).to_double();
        }
        const auto i = tri::pixel_index(x, y, width);
        coverage[i] = tri::ch09::coverage_16(canvas.at(x, y));
        exact[i] = tri::ch09::coverage_16(sum);
      }
    }
  } catch (const std::exception& error) {  // the exact fractions overflowed 128 bits
    copy_text(std::string("the exact area could not be computed: ") + error.what(), message,
              message_capacity);
    return 1;
  }
  copy_text("", message, message_capacity);
  return 0;
}

/// Chapter 03's steps for the first of the two triangles (`vertices` as playground_draw takes
/// them; both must be accepted), as gambetta_interpolate_fill runs them on a width x height
/// canvas: each vertex rounded to its nearest pixel centre, then step 1's sorted vertices, step
/// 2's x01, x12 and x02, step 3's x012 and step 4's x_left and x_right, each with the row of its
/// first value, as JSON. Returns the text's length (written only when it fits in `capacity` with
/// its final zero), or 0 for input the library refuses, a grid out of bounds, or a triangle on
/// one row (which the chapter draws without the arrays).
EMSCRIPTEN_KEEPALIVE std::size_t playground_steps_03(int width, int height, const double* vertices,
                                                     char* out, std::size_t capacity) {
  namespace ch03 = tri::ch03;
  const auto p = first_triangle_pixels(width, height, vertices);
  if (!p) return 0;
  // The same calls as ch03::draw_filled_triangle, keeping what each step returns.
  const ch03::SortedTriangle t = ch03::sort_by_y((*p)[0], (*p)[1], (*p)[2]);
  if (t.p0.y == t.p2.y) return 0;
  const ch03::RowRange rows = ch03::visible_rows(t, height);
  std::string text = "{\"sorted\":[";
  const std::array<glm::ivec2, 3> sorted{t.p0, t.p1, t.p2};
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    text += "[" + std::to_string(sorted[i].x) + "," + std::to_string(sorted[i].y) + "]";
    text += i + 1 < sorted.size() ? "," : "]";
  }
  if (!rows.empty()) {
    ch03::EdgeXs edges = ch03::interpolate_edges(t, rows);
    text += ",\"x01\":" + json_rows(std::max(rows.first, t.p0.y), edges.x01);
    text += ",\"x12\":" + json_rows(std::max(rows.first, t.p1.y), edges.x12);
    text += ",\"x02\":" + json_rows(rows.first, edges.x02);
    std::vector<double> x012 = ch03::concatenate_short_sides(std::move(edges.x01), edges.x12);
    text += ",\"x012\":" + json_rows(rows.first, x012);
    const ch03::LeftRightXs spans = ch03::choose_left_right(edges.x02, std::move(x012));
    text += ",\"x_left\":" + json_rows(rows.first, spans.x_left);
    text += ",\"x_right\":" + json_rows(rows.first, spans.x_right);
  }
  text += "}";
  if (text.size() < capacity) copy_text(text, out, capacity);
  return text.size();
}

/// Chapter 04's six steps for the first of the two triangles (`vertices` as playground_draw
/// takes them; both must be accepted), its vertices rounded to their nearest pixel centres as the
/// registry's scanline fills receive them, each step drawn by the chapter's own step function on
/// a black width x height canvas: 1 the outline, 2 the sorted boundaries (A red, B green), 3 the
/// lower half's boundary points, 4 the lower half filled, 5 the two loops, 6 the single loop.
/// Writes the canvas's RGBA bytes (bottom row first) and returns 0; returns 1 for input the
/// library refuses, a grid out of bounds or no such step.
EMSCRIPTEN_KEEPALIVE int playground_steps_04(int step, int width, int height,
                                             const double* vertices, std::uint8_t* rgba) {
  namespace ch04 = tri::ch04;
  const auto p = first_triangle_pixels(width, height, vertices);
  if (!p) return 1;
  const auto [a, b, c] = *p;
  tri::Canvas canvas(width, height);
  switch (step) {
    case 1:
      ch04::draw_outline(canvas, a, b, c, triangle_colors[0]);
      break;
    case 2:
      ch04::draw_sorted_boundaries(canvas, a, b, c);
      break;
    case 3:
      ch04::draw_lower_half_boundary_points(canvas, a, b, c);
      break;
    case 4:
      ch04::fill_lower_half(canvas, a, b, c, triangle_colors[0]);
      break;
    case 5:
      ch04::fill_two_loops(canvas, a, b, c, triangle_colors[0]);
      break;
    case 6:
      ch04::fill_single_loop(canvas, a, b, c, triangle_colors[0]);
      break;
    default:
      return 1;
  }
  for (const tri::Color& pixel : canvas.pixels()) {
    *rgba++ = pixel.r;
    *rgba++ = pixel.g;
    *rgba++ = pixel.b;
    *rgba++ = pixel.a;
  }
  return 0;
}

}  // extern "C"
