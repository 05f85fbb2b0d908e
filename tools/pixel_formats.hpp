/// @file
/// raster --format: the pixel formats a scene can be drawn in (docs/DESIGN.md section 9). RGBA8 is
/// the shared canvas; index8 (one byte per pixel, a palette of the scene's colours) and mask1 (one
/// bit per pixel, for a one-colour scene) are chapter 08's step 8 canvases, drawn by the drawables
/// that declare those outputs, through their draw_narrow entry (chapter 08's span walker).
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "common/canvas.hpp"
#include "common/scene.hpp"
#include "common/triangle_algorithm.hpp"
#include "measure/drawable.hpp"
#include "measure/render_scene.hpp"

namespace tri {

enum class PixelFormat { rgba8, index8, mask1 };

/// "rgba8", "index8" or "mask1".
std::string_view format_name(PixelFormat format) noexcept;

/// The format a --format value names; "auto" and unknown names give nothing.
std::optional<PixelFormat> parse_format(std::string_view name) noexcept;

/// The output that holds a format's pixels.
Output output_of(PixelFormat format) noexcept;

/// Whether the drawable declares the format among its outputs.
bool draws_format(const Drawable& drawable, PixelFormat format) noexcept;

/// Why the scene cannot be drawn in the format, or nothing when it can: a narrow format draws
/// triangles only, index8 holds at most 255 colours and mask1 one.
std::optional<std::string> format_refusal(const Scene& scene, PixelFormat format);

/// --format auto: the narrowest format that holds the scene and that the drawable draws.
PixelFormat narrowest_format(const Scene& scene, const Drawable& drawable);

/// A narrow format's draw of the scene's triangles (validated once, as draw_triangles does) with
/// an algorithm's draw_narrow entry, kept ready to repeat for --bench; expanded() gives the RGBA8
/// canvas it stands for, the same pixels as an RGBA8 draw by a drawable that declares the narrow
/// formats.
class NarrowRender {
 public:
  /// Prepares the triangles, canvas and palette (preconditions: format_refusal(scene, format) is
  /// empty, format is not rgba8 and the algorithm has a draw_narrow entry).
  NarrowRender(const Scene& scene, PixelFormat format, const TriangleAlgorithm& algorithm);
  ~NarrowRender();
  NarrowRender(const NarrowRender&) = delete;
  NarrowRender& operator=(const NarrowRender&) = delete;

  /// Draws every valid triangle; returns how many were refused (non-finite or out of range).
  /// on_progress hears how many triangles are done every progress_every triangles and after each
  /// band of rows of a huge triangle (render_scene's band_rows_for), which is then drawn in bands
  /// of step 8's spans.
  std::size_t draw(const ProgressFunction& on_progress = {});
  static constexpr std::size_t progress_every = 4096;
  /// The RGBA8 picture: the background where no triangle drew, else the triangle's colour.
  Canvas expanded() const;

 private:
  struct State;
  const Scene& scene_;
  PixelFormat format_;
  const TriangleAlgorithm& algorithm_;
  std::unique_ptr<State> state_;
};

}  // namespace tri
