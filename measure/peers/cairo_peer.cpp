#include "measure/peers/library_peers.hpp"

#include <cairo.h>

#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>

#include "measure/peers/byte_coverage_peer.hpp"
#include "measure/peers/y_down_peer.hpp"

namespace tri {
namespace {

// A cairo image surface and a drawing context on it, filling one triangle path at a time with
// the given anti-aliasing and operator. With CAIRO_OPERATOR_ADD each fill adds its coverage to
// the pixel (saturating at 255), as a summed coverage canvas does, instead of compositing it over
// what is there.
class CairoSurface {
 public:
  CairoSurface(int width, int height, cairo_format_t format, cairo_antialias_t antialias,
               cairo_operator_t op)
      : surface_(cairo_image_surface_create(format, width, height), cairo_surface_destroy),
        context_(nullptr, cairo_destroy) {
    if (cairo_surface_status(surface_.get()) != CAIRO_STATUS_SUCCESS) {
      throw std::runtime_error("cairo could not create a " + std::to_string(width) + "x" +
                               std::to_string(height) + " image surface");
    }
    context_.reset(cairo_create(surface_.get()));
    cairo_set_antialias(context_.get(), antialias);
    cairo_set_fill_rule(context_.get(), CAIRO_FILL_RULE_WINDING);
    cairo_set_operator(context_.get(), op);
    cairo_set_source_rgba(context_.get(), 1, 1, 1, 1);
  }

  void set_color(Color c) noexcept {
    cairo_set_source_rgba(context_.get(), c.r / 255.0, c.g / 255.0, c.b / 255.0, 1);
  }

  // One path of three vertices, already in cairo's y-down space, filled.
  void draw(const YDownTriangle& v) noexcept {
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

  // The alpha of pixel (x, row) of an A8 surface, row counted from the top (after flush()).
  std::uint8_t alpha(int x, int row) noexcept {
    return cairo_image_surface_get_data(surface_.get())[row * stride() + x];
  }
  void flush() noexcept { cairo_surface_flush(surface_.get()); }
  // The same, flushing first.
  std::uint8_t value(int x, int row) noexcept {
    flush();
    return alpha(x, row);
  }

 private:
  int stride() noexcept { return cairo_image_surface_get_stride(surface_.get()); }

  std::unique_ptr<cairo_surface_t, void (*)(cairo_surface_t*)> surface_;
  std::unique_ptr<cairo_t, void (*)(cairo_t*)> context_;
};

// The coverage peer's image: an A8 surface with cairo's default anti-aliasing, adding.
struct CairoAlpha : CairoSurface {
  CairoAlpha(int width, int height)
      : CairoSurface(width, height, CAIRO_FORMAT_A8, CAIRO_ANTIALIAS_DEFAULT, CAIRO_OPERATOR_ADD) {}
};

struct CairoTriangle {
  YDownTriangle vertices;
  Color color;
};

std::vector<CairoTriangle> to_cairo(std::span<const SceneTriangle> triangles, int height) {
  require_within(triangles, height, cairo_coordinate_limit, "cairo");
  std::vector<CairoTriangle> out;
  out.reserve(triangles.size());
  for (const SceneTriangle& t : triangles) {
    out.push_back({to_y_down(t, height), t.color});
  }
  return out;
}

}  // namespace

WriteCounts cairo_write_counts(int width, int height, std::span<const SceneTriangle> triangles) {
  const std::vector<CairoTriangle> converted = to_cairo(triangles, height);
  CairoSurface mask(width, height, CAIRO_FORMAT_A8, CAIRO_ANTIALIAS_NONE, CAIRO_OPERATOR_OVER);
  return count_each_alone(
      width, height, triangles,
      [&](std::size_t t) {
        mask.clear();
        mask.draw(converted[t].vertices);
        mask.flush();
      },
      [&](int x, int top_row) { return mask.alpha(x, top_row) != 0; });
}

namespace {

// One fill call per triangle, its colour set before; surface and converted triangles ready
// before the clock.
Timing time_cairo_draw(const PreparedScene& prepared, const TimingPlan& plan) {
  const std::vector<CairoTriangle> triangles = to_cairo(prepared.triangles, prepared.scene.height);
  CairoSurface canvas(prepared.scene.width, prepared.scene.height, CAIRO_FORMAT_ARGB32,
                      CAIRO_ANTIALIAS_NONE, CAIRO_OPERATOR_OVER);
  return time_runs(
      [&] {
        for (const CairoTriangle& t : triangles) {
          canvas.set_color(t.color);
          canvas.draw(t.vertices);
        }
        canvas.flush();
      },
      plan);
}

}  // namespace

ExternalPeer cairo_peer() {
  return in_process_peer(
      aliased_peer_description("cairo_no_antialias",
                               "cairo_fill of one triangle path, CAIRO_ANTIALIAS_NONE",
                               CoverageRule::approximate, false),
      "cairo", time_cairo_draw, cairo_write_counts);
}

CoveragePeer cairo_coverage_peer() {
  return byte_coverage_peer<CairoAlpha>(
      coverage_peer_description(
          "cairo_antialias",
          "cairo_fill with its default anti-aliasing: the area in x over 15 rows"),
      0, "cairo", cairo_coordinate_limit);
}

std::string cairo_version() {
  return std::string("cairo ") + cairo_version_string();
}

}  // namespace tri
