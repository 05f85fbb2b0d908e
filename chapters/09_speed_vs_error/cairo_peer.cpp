#include "chapters/09_speed_vs_error/cairo_peer.hpp"

#include <cairo.h>

#include <cstring>
#include <memory>
#include <numeric>
#include <stdexcept>
#include <string>

#include "chapters/09_speed_vs_error/y_down_peer.hpp"

namespace tri::ch09 {
namespace {

// A cairo image surface and a drawing context on it, set up for aliased fills.
class CairoCanvas {
 public:
  CairoCanvas(int width, int height, cairo_format_t format)
      : surface_(cairo_image_surface_create(format, width, height), cairo_surface_destroy),
        context_(nullptr, cairo_destroy) {
    if (cairo_surface_status(surface_.get()) != CAIRO_STATUS_SUCCESS) {
      throw std::runtime_error("cairo could not create a " + std::to_string(width) + "x" +
                               std::to_string(height) + " image surface");
    }
    context_.reset(cairo_create(surface_.get()));
    cairo_set_antialias(context_.get(), CAIRO_ANTIALIAS_NONE);
    cairo_set_fill_rule(context_.get(), CAIRO_FILL_RULE_WINDING);
    cairo_set_source_rgba(context_.get(), 1, 1, 1, 1);
  }

  void set_color(Color c) noexcept {
    cairo_set_source_rgba(context_.get(), c.r / 255.0, c.g / 255.0, c.b / 255.0, 1);
  }

  // One path of three vertices, already in cairo's y-down space, filled.
  void fill(const glm::dvec2 (&v)[3]) noexcept {
    cairo_t* cr = context_.get();
    cairo_move_to(cr, v[0].x, v[0].y);
    cairo_line_to(cr, v[1].x, v[1].y);
    cairo_line_to(cr, v[2].x, v[2].y);
    cairo_close_path(cr);
    cairo_fill(cr);
  }

  void clear() noexcept {
    cairo_surface_flush(surface_.get());
    std::memset(cairo_image_surface_get_data(surface_.get()), 0,
                static_cast<std::size_t>(stride()) *
                    static_cast<std::size_t>(cairo_image_surface_get_height(surface_.get())));
    cairo_surface_mark_dirty(surface_.get());
  }

  // The alpha of pixel (x, row) of an A8 surface, row counted from the top.
  std::uint8_t alpha(int x, int row) noexcept {
    return cairo_image_surface_get_data(surface_.get())[row * stride() + x];
  }
  void flush() noexcept { cairo_surface_flush(surface_.get()); }

 private:
  int stride() noexcept { return cairo_image_surface_get_stride(surface_.get()); }

  std::unique_ptr<cairo_surface_t, void (*)(cairo_surface_t*)> surface_;
  std::unique_ptr<cairo_t, void (*)(cairo_t*)> context_;
};

struct CairoTriangle {
  glm::dvec2 vertices[3];
  Color color;
};

std::vector<CairoTriangle> to_cairo(std::span<const SceneTriangle> triangles, int height) {
  require_within(triangles, height, cairo_coordinate_limit, "cairo");
  std::vector<CairoTriangle> out;
  out.reserve(triangles.size());
  for (const SceneTriangle& t : triangles) {
    out.push_back({{to_y_down(t.vertices[0], height), to_y_down(t.vertices[1], height),
                    to_y_down(t.vertices[2], height)},
                   t.color});
  }
  return out;
}

}  // namespace

WriteCounts cairo_write_counts(int width, int height, std::span<const SceneTriangle> triangles) {
  const std::vector<CairoTriangle> converted = to_cairo(triangles, height);
  CairoCanvas mask(width, height, CAIRO_FORMAT_A8);
  WriteCounts result;
  result.counts.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0);
  for (std::size_t t = 0; t < converted.size(); ++t) {
    mask.clear();
    mask.fill(converted[t].vertices);
    mask.flush();
    const PixelWindow window = pixels_around(triangles[t], width, height);
    for (int y = window.y_begin; y < window.y_end; ++y) {
      for (int x = window.x_begin; x < window.x_end; ++x) {
        if (mask.alpha(x, height - 1 - y) != 0) {
          ++result.counts[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                          static_cast<std::size_t>(x)];
        }
      }
    }
  }
  return result;
}

namespace {

// One fill call per triangle, its colour set before; surface and converted triangles ready
// before the clock.
Timing time_cairo_draw(const PreparedScene& prepared, const TimingPlan& plan) {
  const std::vector<CairoTriangle> triangles = to_cairo(prepared.triangles, prepared.scene.height);
  CairoCanvas canvas(prepared.scene.width, prepared.scene.height, CAIRO_FORMAT_ARGB32);
  return time_runs(
      [&] {
        for (const CairoTriangle& t : triangles) {
          canvas.set_color(t.color);
          canvas.fill(t.vertices);
        }
        canvas.flush();
      },
      plan);
}

}  // namespace

ExternalPeer cairo_peer() {
  return {"cairo_no_antialias",
          "external",
          "approximate",
          false,
          [](const PreparedScene& prepared, const TimingPlan& plan) {
            PeerResult result;
            result.timing = time_cairo_draw(prepared, plan);
            const WriteCounts drawn =
                cairo_write_counts(prepared.scene.width, prepared.scene.height, prepared.triangles);
            result.written_pixels =
                std::accumulate(drawn.counts.begin(), drawn.counts.end(), std::uint64_t{0});
            result.error = measure_error(cairo_write_counts, prepared.error_scene);
            return result;
          },
          time_cairo_draw};
}

}  // namespace tri::ch09
