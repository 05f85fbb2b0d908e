// Chapter 07's figures: what exact coverage changes. A shared-edge mesh drawn by chapter 06 and by
// chapter 07, shown as write counts, and two triangles sharing an edge drawn both ways.
#include <cmath>
#include <string>
#include <vector>

#include "coverage_oracle.hpp"
#include "edge_function_fill.hpp"
#include "figures.hpp"
#include "fill.hpp"
#include "fixed_point.hpp"
#include "random.hpp"

namespace {

using tri::Canvas;
using tri::Color;
using tri::Triangle;

constexpr int mesh_size = 48;

// A 6x6 grid of cells over the canvas, vertices jittered on the 1/256 grid, two triangles a cell.
std::vector<Triangle> jittered_mesh() {
  tri::Random random(7);
  constexpr int cells = 6;
  const double step = (mesh_size + 8.0) / cells;
  std::vector<glm::dvec2> points;
  for (int j = 0; j <= cells; ++j) {
    for (int i = 0; i <= cells; ++i) {
      const bool border = i == 0 || j == 0 || i == cells || j == cells;
      const double jx = border ? 0 : random.real(-0.15, 0.15) * step;
      const double jy = border ? 0 : random.real(-0.15, 0.15) * step;
      points.emplace_back(std::round((-4 + i * step + jx) * 256) / 256,
                          std::round((-4 + j * step + jy) * 256) / 256);
    }
  }
  const auto at = [&](int i, int j) {
    return points[static_cast<std::size_t>(j * (cells + 1) + i)];
  };
  std::vector<Triangle> mesh;
  for (int j = 0; j < cells; ++j) {
    for (int i = 0; i < cells; ++i) {
      mesh.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      mesh.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return mesh;
}

// Write counts as colours: red = gap (never drawn), grey = once, yellow = twice, white = more.
Canvas counts_picture(const Canvas& counted) {
  Canvas picture(counted.width(), counted.height());
  for (int y = 0; y < counted.height(); ++y) {
    for (int x = 0; x < counted.width(); ++x) {
      const auto n = counted.write_count(x, y);
      const Color c = n == 0   ? tri::colors::red
                      : n == 1 ? Color{110, 110, 110, 255}
                      : n == 2 ? tri::colors::yellow
                               : tri::colors::white;
      picture.put_pixel(x, y, c);
    }
  }
  return picture;
}

using DrawFunction = void (*)(Canvas&, const Triangle&, Color);

// The earlier chapters' fills as their registry entries draw them (vertices rounded first).
constexpr DrawFunction draw_barycentric =
    tri::draw_at_nearest_pixels<tri::ch06::fill_triangle_barycentric<double>>;
constexpr DrawFunction draw_edge_function =
    tri::draw_at_nearest_pixels<tri::ch05::fill_triangle_edge_function>;

Canvas mesh_counts(DrawFunction draw) {
  Canvas canvas(mesh_size, mesh_size);
  canvas.enable_write_counts();
  for (const Triangle& t : jittered_mesh()) draw(canvas, t, tri::colors::white);
  return counts_picture(canvas);
}

// Two triangles sharing the edge (2,2)-(14,10), which passes through the centres (5,4), (8,6) and
// (11,8): red and blue, and magenta where both drew.
Canvas shared_edge(DrawFunction draw) {
  Canvas canvas(17, 13, Color{30, 30, 30, 255});
  Canvas red(17, 13), blue(17, 13);
  red.enable_write_counts();
  blue.enable_write_counts();
  draw(red, {{{2, 2}, {14, 10}, {2, 11}}}, tri::colors::red);
  draw(blue, {{{14, 10}, {2, 2}, {15, 1}}}, tri::colors::blue);
  for (int y = 0; y < canvas.height(); ++y) {
    for (int x = 0; x < canvas.width(); ++x) {
      const bool r = red.write_count(x, y) > 0, b = blue.write_count(x, y) > 0;
      if (r || b)
        canvas.put_pixel(x, y,
                         r && b ? tri::colors::magenta
                         : r    ? tri::colors::red
                                : tri::colors::blue);
    }
  }
  return canvas;
}

}  // namespace

int main(int argc, char** argv) {
  return tri::run_chapter_program(
      argc, argv, "07_exact_coverage",
      "Chapter 07, exact coverage: a jittered mesh drawn by chapter 06's barycentric fill and by\n"
      "the fixed-point rasterizer, as write counts (07_mesh_counts_barycentric.png,\n"
      "07_mesh_counts_fixed_point.png: red = gap, grey = once, yellow = twice), and two triangles\n"
      "sharing an edge through pixel centres, drawn inclusively and by the top-left rule\n"
      "(07_shared_edge_inclusive.png, 07_shared_edge_top_left.png: magenta = drawn twice).",
      [](tri::FigureWriter& figures) {
        figures.save_png("07_mesh_counts_barycentric",
                         tri::magnified(mesh_counts(draw_barycentric), 6));
        figures.save_png("07_mesh_counts_fixed_point",
                         tri::magnified(mesh_counts(tri::ch07::draw_triangle_fixed_point_8), 6));
        figures.save_png("07_shared_edge_inclusive",
                         tri::magnified(shared_edge(draw_edge_function), 16));
        figures.save_png("07_shared_edge_top_left",
                         tri::magnified(shared_edge(tri::ch07::draw_triangle_fixed_point_8), 16));
      });
}
