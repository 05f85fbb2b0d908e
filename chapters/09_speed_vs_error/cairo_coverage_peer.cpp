#include <cairo.h>

#include <cstring>
#include <memory>
#include <stdexcept>

#include "chapters/09_speed_vs_error/byte_coverage_peer.hpp"
#include "chapters/09_speed_vs_error/library_peers.hpp"

namespace tri::ch09 {
namespace {

// An A8 surface filled with cairo's default anti-aliasing. The ADD operator makes each fill add
// its coverage to the pixel (saturating at 255), as a summed coverage canvas does, instead of
// compositing it over what is there.
class CairoAlpha {
 public:
  CairoAlpha(int width, int height)
      : height_(height),
        surface_(cairo_image_surface_create(CAIRO_FORMAT_A8, width, height), cairo_surface_destroy),
        context_(nullptr, cairo_destroy) {
    if (cairo_surface_status(surface_.get()) != CAIRO_STATUS_SUCCESS) {
      throw std::runtime_error("cairo could not create an A8 surface");
    }
    context_.reset(cairo_create(surface_.get()));
    cairo_set_antialias(context_.get(), CAIRO_ANTIALIAS_DEFAULT);
    cairo_set_operator(context_.get(), CAIRO_OPERATOR_ADD);
    cairo_set_source_rgba(context_.get(), 0, 0, 0, 1);
  }

  void clear() noexcept {
    cairo_surface_flush(surface_.get());
    std::memset(cairo_image_surface_get_data(surface_.get()), 0,
                static_cast<std::size_t>(cairo_image_surface_get_stride(surface_.get())) *
                    static_cast<std::size_t>(height_));
    cairo_surface_mark_dirty(surface_.get());
  }
  void draw(const SceneTriangle& t) noexcept {
    cairo_t* cr = context_.get();
    const glm::dvec2 a = to_y_down(t.vertices[0], height_), b = to_y_down(t.vertices[1], height_),
                     c = to_y_down(t.vertices[2], height_);
    cairo_move_to(cr, a.x, a.y);
    cairo_line_to(cr, b.x, b.y);
    cairo_line_to(cr, c.x, c.y);
    cairo_close_path(cr);
    cairo_fill(cr);
  }
  std::uint8_t value(int x, int top_row) noexcept {
    cairo_surface_flush(surface_.get());
    return cairo_image_surface_get_data(
        surface_.get())[top_row * cairo_image_surface_get_stride(surface_.get()) + x];
  }

 private:
  int height_;
  std::unique_ptr<cairo_surface_t, void (*)(cairo_surface_t*)> surface_;
  std::unique_ptr<cairo_t, void (*)(cairo_t*)> context_;
};

}  // namespace

CoveragePeer cairo_coverage_peer() {
  return byte_coverage_peer<CairoAlpha>("cairo_antialias", "area in x over 15 rows", 0, "cairo",
                                        cairo_coordinate_limit);
}

}  // namespace tri::ch09
