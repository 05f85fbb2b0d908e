/// @file
/// The playground's C++ side, compiled to WebAssembly by em++ only (docs/playground/CMakeLists.txt):
/// the registry's list of algorithms, and two triangles drawn with a registered algorithm and with
/// chapter 07's oracle, as per-pixel write counts. Every pixel decision is the chapters' code; the
/// page's JavaScript only draws the results and handles input. The functions keep no state: the
/// page owns every buffer and passes it in.
#include <emscripten/emscripten.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "chapters/07_exact_coverage/coverage_oracle.hpp"
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
      const auto i = static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                     static_cast<std::size_t>(x);
      last_writer[i] = c == triangle_colors[0] ? 1 : c == triangle_colors[1] ? 2 : 0;
    }
  }
  *outside_writes = static_cast<std::uint32_t>(
      std::min<std::uint64_t>(canvas.outside_writes(), UINT32_MAX));
}

}  // namespace

extern "C" {

/// Writes the registered algorithms, one a line: name, chapter, rule, 1 when threaded (else 0)
/// and summary, tab-separated, in the registry's order: the triangle algorithms, then the
/// coverage ones (rule area). Returns the text's length; it is written only when it fits in
/// `capacity` bytes with its final zero.
EMSCRIPTEN_KEEPALIVE std::size_t playground_algorithms(char* out, std::size_t capacity) {
  std::string text;
  for (const auto& a : tri::registered_algorithms()) {
    text.append(a.name).append("\t").append(a.chapter).append("\t");
    text.append(tri::rule_name(a.rule)).append(a.threaded ? "\t1\t" : "\t0\t");
    text.append(a.summary).append("\n");
  }
  for (const auto& a : tri::registered_area_algorithms()) {
    text.append(a.name).append("\t").append(a.chapter).append("\t");
    text.append(tri::rule_name(a.rule)).append("\t0\t").append(a.summary).append("\n");
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
  if (width < 1 || width > max_width || height < 1 || height > max_height) {
    copy_text("the grid must be 1 to 64 pixels wide and 1 to 48 high", message,
              message_capacity);
    return 3;
  }
  const auto algorithms = tri::registered_algorithms();
  const tri::TriangleAlgorithm* algorithm = tri::find_algorithm(algorithms, name);
  if (algorithm == nullptr) {
    copy_text(std::string("no triangle algorithm is registered as '") + name + "'", message,
              message_capacity);
    return 2;
  }
  std::array<tri::SceneTriangle, 2> triangles;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    for (std::size_t v = 0; v < 3; ++v) {
      triangles[t].vertices[v] = {vertices[6 * t + 2 * v], vertices[6 * t + 2 * v + 1]};
    }
    triangles[t].color = triangle_colors[t];
  }
  // raster writes no file when a triangle is refused; the page likewise draws nothing.
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const tri::DrawResult result = tri::validate_triangle(triangles[t].vertices);
    if (result != tri::DrawResult::drawn) {
      copy_text(std::string(t == 0 ? "triangle 1: " : "triangle 2: ") +
                    std::string(tri::describe(result)),
                message, message_capacity);
      return 1;
    }
  }
  const tri::TriangleAlgorithm oracle{.name = "oracle",
                                      .chapter = "07_exact_coverage",
                                      .rule = tri::CoverageRule::top_left,
                                      .summary = "chapter 07's oracle",
                                      .draw = tri::ch07::draw_triangle_oracle};
  draw_counted(*algorithm, width, height, triangles, counts, last_writer, &outside_writes[0]);
  draw_counted(oracle, width, height, triangles, oracle_counts, oracle_last_writer,
               &outside_writes[1]);
  copy_text("", message, message_capacity);
  return 0;
}

}  // extern "C"
