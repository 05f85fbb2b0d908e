#include "tools/pixel_formats.hpp"

#include <algorithm>
#include <array>
#include <utility>
#include <vector>

#include "chapters/08_fast_exact/narrow_canvases.hpp"
#include "common/enum_names.hpp"
#include "measure/render_scene.hpp"

namespace tri {
namespace {

// The scene's triangle colours in order of first appearance.
std::vector<Color> triangle_colors(const Scene& scene) {
  std::vector<Color> colors;
  for (const SceneTriangle& t : scene_triangles(scene)) {
    if (std::find(colors.begin(), colors.end(), t.color) == colors.end()) colors.push_back(t.color);
  }
  return colors;
}

constexpr std::size_t max_palette_colors = 255;  // index 0 is the background

constexpr auto format_names = all_names<PixelFormat::mask1>({{PixelFormat::rgba8, "rgba8"},
                                                             {PixelFormat::index8, "index8"},
                                                             {PixelFormat::mask1, "mask1"}});

}  // namespace

std::string_view format_name(PixelFormat format) noexcept {
  return name_in(format_names, format, "rgba8");
}

std::optional<PixelFormat> parse_format(std::string_view name) noexcept {
  return value_named(format_names, name);
}

Output output_of(PixelFormat format) noexcept {
  switch (format) {
    case PixelFormat::index8:
      return Output::index8;
    case PixelFormat::mask1:
      return Output::mask1;
    case PixelFormat::rgba8:
      break;
  }
  return Output::rgba8;
}

bool draws_format(const Drawable& drawable, PixelFormat format) noexcept {
  return drawable.writes(output_of(format));
}

std::optional<std::string> format_refusal(const Scene& scene, PixelFormat format) {
  if (format == PixelFormat::rgba8) return std::nullopt;
  const std::size_t lines = scene.primitives.size() - count_triangles(scene);
  if (lines > 0) {
    return std::string(format_name(format)) + " draws triangles only, and the scene has " +
           std::to_string(lines) + " line(s)";
  }
  const std::size_t colors = triangle_colors(scene).size();
  const std::size_t most = format == PixelFormat::mask1 ? 1 : max_palette_colors;
  if (colors > most) {
    return std::string(format_name(format)) + " holds " + std::to_string(most) +
           (most == 1 ? " colour" : " colours") + " besides the background, and the scene's " +
           "triangles have " + std::to_string(colors);
  }
  return std::nullopt;
}

PixelFormat narrowest_format(const Scene& scene, const Drawable& drawable) {
  for (const PixelFormat f : {PixelFormat::mask1, PixelFormat::index8}) {
    if (draws_format(drawable, f) && !format_refusal(scene, f)) return f;
  }
  return PixelFormat::rgba8;
}

struct NarrowRender::State {
  PreparedBatch triangles;             // validated once, drawn every frame
  std::vector<Color> palette;          // palette[0] is the background
  std::vector<std::uint8_t> index_of;  // each accepted triangle's palette index
  ch08::IndexCanvas indices;
  ch08::MaskCanvas mask;
  NarrowTarget target;
};

NarrowRender::NarrowRender(const Scene& scene, PixelFormat format,
                           const TriangleAlgorithm& algorithm)
    : scene_(scene), format_(format), algorithm_(algorithm) {
  const bool bytes = format == PixelFormat::index8;
  state_ = std::make_unique<State>(State{PreparedBatch(scene_triangles(scene)),
                                         {scene.background},
                                         {},
                                         ch08::IndexCanvas(bytes ? scene.width : 0, scene.height),
                                         ch08::MaskCanvas(bytes ? 0 : scene.width, scene.height),
                                         {}});
  for (const Color& c : triangle_colors(scene)) state_->palette.push_back(c);
  for (const SceneTriangle& t : state_->triangles.triangles()) {
    const auto at = std::find(state_->palette.begin() + 1, state_->palette.end(), t.color);
    state_->index_of.push_back(static_cast<std::uint8_t>(at - state_->palette.begin()));
  }
  if (bytes) {
    state_->target = {.indices = &state_->indices, .index_of = state_->index_of};
  } else {
    state_->target = {.mask = &state_->mask};
  }
}

NarrowRender::~NarrowRender() = default;

std::size_t NarrowRender::draw(const ProgressFunction& on_progress) {
  const std::span<const SceneTriangle> triangles = state_->triangles.triangles();
  if (!on_progress) {
    algorithm_.draw_narrow(state_->target, triangles);
    return state_->triangles.refused();
  }
  // With progress: runs of at most progress_every triangles through the algorithm's narrow draw,
  // and a huge triangle alone, in bands of rows of step 8's spans (the same pixels), a report
  // after each band.
  const int width = scene_.width, height = scene_.height;
  std::size_t run_start = 0;
  const auto draw_run = [&](std::size_t end) {
    if (end == run_start) return;
    NarrowTarget part = state_->target;
    if (format_ == PixelFormat::index8) part.index_of = part.index_of.subspan(run_start);
    algorithm_.draw_narrow(part, triangles.subspan(run_start, end - run_start));
    run_start = end;
    on_progress(static_cast<double>(end));
  };
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    const Triangle& t = triangles[i].vertices;
    const int rows = band_rows_for(t, width, height);
    if (rows > 0) {
      draw_run(i);
      for_each_band(
          t, width, height, rows,
          [&](int first, int last) {
            if (format_ == PixelFormat::index8) {
              ch08::draw_triangle_spans_index8_rows(state_->indices, t, state_->index_of[i], first,
                                                    last);
            } else {
              ch08::draw_triangle_spans_mask1_rows(state_->mask, t, first, last);
            }
          },
          [&](double share) { on_progress(static_cast<double>(i) + share); });
      run_start = i + 1;
    } else if (i + 1 - run_start == progress_every) {
      draw_run(i + 1);
    }
  }
  draw_run(triangles.size());
  return state_->triangles.refused();
}

Canvas NarrowRender::expanded() const {
  Canvas canvas = make_canvas(scene_);
  const Color one = state_->palette.size() > 1 ? state_->palette[1] : scene_.background;
  for (int y = 0; y < canvas.height(); ++y) {
    for (int x = 0; x < canvas.width(); ++x) {
      if (format_ == PixelFormat::index8) {
        canvas.put_pixel(x, y, state_->palette[state_->indices.index(x, y)]);
      } else if (state_->mask.covered(x, y)) {
        canvas.put_pixel(x, y, one);
      }
    }
  }
  return canvas;
}

}  // namespace tri
