/// @file
/// Mesa's software rasterizer, llvmpipe, drawing into memory through OSMesa: the external peer
/// the report measures beside the book's algorithms. Built only when OSMesa is installed.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "common/scene.hpp"
#include "measure/error_metrics.hpp"

namespace tri {

/// An OSMesa context current on this thread while the object lives, drawing into a width x height
/// buffer it owns with the canvas's coordinates (y up, pixel (i, j) sampled at (i, j)).
class LlvmpipeCanvas {
 public:
  /// What the buffer holds: the picture (RGBA8, as our canvas) or write counts (a float per
  /// channel, every triangle adds 1 to red by additive blending, so counts are exact).
  enum class Pixels { rgba8, write_counts };

  /// Where GL's viewport lies: far past the buffer, so llvmpipe never clips a triangle near it
  /// (what the peer uses), or just the buffer, as a windowed program would set it (the
  /// tests use it to show that clipping moves pixels).
  enum class Viewport { guard_band, buffer_only };

  /// Throws std::runtime_error when OSMesa cannot create or bind the context.
  LlvmpipeCanvas(int width, int height, Pixels pixels, Viewport viewport = Viewport::guard_band);
  ~LlvmpipeCanvas();
  LlvmpipeCanvas(const LlvmpipeCanvas&) = delete;
  LlvmpipeCanvas& operator=(const LlvmpipeCanvas&) = delete;

  /// GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
  std::string renderer() const;

  /// GL_VERSION, e.g. "4.5 (Compatibility Profile) Mesa 22.3.6".
  std::string version() const;

  /// Copies the triangles into a GL vertex buffer, once, so draw() only draws.
  void upload(std::span<const SceneTriangle> triangles);

  /// Draws the uploaded triangles and waits until they are in the buffer (glFinish).
  void draw();

  /// Clears, draws the triangles once and returns the counts (Pixels::write_counts only).
  WriteCounts write_counts(std::span<const SceneTriangle> triangles);

  /// The colour of pixel (x, y) (Pixels::rgba8 only).
  Color pixel(int x, int y) const;

 private:
  struct Context;
  std::unique_ptr<Context> context_;
};

/// A CountingDraw for measure_error: llvmpipe's write counts on a fresh width x height buffer.
WriteCounts llvmpipe_write_counts(
    int width, int height, std::span<const SceneTriangle> triangles,
    LlvmpipeCanvas::Viewport viewport = LlvmpipeCanvas::Viewport::guard_band);

}  // namespace tri
