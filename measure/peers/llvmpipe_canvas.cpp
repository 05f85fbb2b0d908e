#include "measure/peers/llvmpipe_canvas.hpp"

#define GL_GLEXT_PROTOTYPES 1  // glGenBuffers and friends, which OSMesa's library exports
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>

namespace tri {

struct LlvmpipeCanvas::Context {
  OSMesaContext gl = nullptr;
  int width = 0;
  int height = 0;
  Pixels pixels = Pixels::rgba8;
  std::vector<std::uint8_t> rgba8;  // the buffer OSMesa draws into, bottom row first
  std::vector<float> rgba_float;
  GLuint vertex_buffer = 0;
  GLsizei vertices = 0;
};

namespace {

// One vertex as the buffer holds it: position, then the triangle's colour.
struct Vertex {
  float x, y;
  std::uint8_t r, g, b, a;
};

}  // namespace

LlvmpipeCanvas::LlvmpipeCanvas(int width, int height, Pixels pixels, Viewport viewport)
    : context_(std::make_unique<Context>()) {
  Context& c = *context_;
  c.width = width;
  c.height = height;
  c.pixels = pixels;
  c.gl = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, nullptr);
  if (c.gl == nullptr) throw std::runtime_error("OSMesa could not create a context");
  const auto count = static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4;
  const bool bound =
      pixels == Pixels::rgba8
          ? (c.rgba8.assign(count, 0),
             OSMesaMakeCurrent(c.gl, c.rgba8.data(), GL_UNSIGNED_BYTE, width, height))
          : (c.rgba_float.assign(count, 0.0f),
             OSMesaMakeCurrent(c.gl, c.rgba_float.data(), GL_FLOAT, width, height));
  if (!bound) {
    OSMesaDestroyContext(c.gl);
    throw std::runtime_error("OSMesa could not bind a " + std::to_string(width) + "x" +
                             std::to_string(height) + " buffer");
  }
  // llvmpipe clips triangles that cross the viewport, and the new vertices move the edges a
  // little: with a viewport of just the buffer, triangles crossing its border lost or gained
  // pixels. So the viewport reaches one canvas size past every side (a guard band), and its
  // side is a power of two, so the float transforms to NDC and back are exact, not just close.
  int x0 = 0, y0 = 0, view_width = width, view_height = height;
  if (viewport == Viewport::guard_band) {
    const int side =
        static_cast<int>(std::bit_ceil(static_cast<unsigned>(std::max(width, height))));
    GLint max_viewport[2] = {0, 0};
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, max_viewport);
    const auto max_side = static_cast<unsigned>(std::min(max_viewport[0], max_viewport[1]));
    view_width = view_height = std::min(4 * side, static_cast<int>(std::bit_floor(max_side)));
    x0 = y0 = -(view_width - side) / 2;
  }
  glViewport(x0, y0, view_width, view_height);
  // Window pixel (i, j) is sampled at (i + 0.5, j + 0.5); ours at (i, j): shift by half a pixel.
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(x0 - 0.5, x0 + view_width - 0.5, y0 - 0.5, y0 + view_height - 0.5, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_DITHER);
  glShadeModel(GL_FLAT);  // one colour per triangle, as every algorithm of the book draws
  if (pixels == Pixels::write_counts) {
    glClearColor(0, 0, 0, 0);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);        // every covered sample adds the incoming 1 to what is there
    glColor4f(1.0f, 0.0f, 0.0f, 0.0f);  // no colour array in this mode: every vertex is this
  }
  glGenBuffers(1, &c.vertex_buffer);
}

LlvmpipeCanvas::~LlvmpipeCanvas() {
  glDeleteBuffers(1, &context_->vertex_buffer);
  OSMesaDestroyContext(context_->gl);
}

std::string LlvmpipeCanvas::renderer() const {
  const auto* name = glGetString(GL_RENDERER);
  return name == nullptr ? "unknown" : reinterpret_cast<const char*>(name);
}

std::string LlvmpipeCanvas::version() const {
  const auto* text = glGetString(GL_VERSION);
  return text == nullptr ? "unknown" : reinterpret_cast<const char*>(text);
}

void LlvmpipeCanvas::upload(std::span<const SceneTriangle> triangles) {
  std::vector<Vertex> vertices;
  vertices.reserve(triangles.size() * 3);
  for (const SceneTriangle& t : triangles) {
    for (const auto& v : t.vertices) {
      // The suites' coordinates (integers and 1/256 steps below 2^15) are exact in a float.
      vertices.push_back({static_cast<float>(v.x), static_cast<float>(v.y), t.color.r, t.color.g,
                          t.color.b, t.color.a});
    }
  }
  Context& c = *context_;
  c.vertices = static_cast<GLsizei>(vertices.size());
  glBindBuffer(GL_ARRAY_BUFFER, c.vertex_buffer);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(Vertex)),
               vertices.data(), GL_STATIC_DRAW);
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(2, GL_FLOAT, sizeof(Vertex), reinterpret_cast<const void*>(0));
  if (c.pixels == Pixels::rgba8) {
    glEnableClientState(GL_COLOR_ARRAY);
    glColorPointer(4, GL_UNSIGNED_BYTE, sizeof(Vertex),
                   reinterpret_cast<const void*>(offsetof(Vertex, r)));
  }
}

// [listing llvmpipe_draw]
void LlvmpipeCanvas::draw() {
  glDrawArrays(GL_TRIANGLES, 0, context_->vertices);
  glFinish();
}
// [/listing]

WriteCounts LlvmpipeCanvas::write_counts(std::span<const SceneTriangle> triangles) {
  Context& c = *context_;
  if (c.pixels != Pixels::write_counts) {
    throw std::logic_error("write_counts needs a LlvmpipeCanvas made for write counts");
  }
  upload(triangles);
  glClear(GL_COLOR_BUFFER_BIT);
  draw();
  WriteCounts drawn;
  drawn.counts.resize(static_cast<std::size_t>(c.width) * static_cast<std::size_t>(c.height));
  for (std::size_t i = 0; i < drawn.counts.size(); ++i) {
    drawn.counts[i] = static_cast<std::uint32_t>(std::lround(c.rgba_float[i * 4]));
  }
  return drawn;  // GL clips at the buffer's edges and rejects nothing: both stay 0
}

Color LlvmpipeCanvas::pixel(int x, int y) const {
  const Context& c = *context_;
  if (c.pixels != Pixels::rgba8) throw std::logic_error("pixel needs an RGBA8 LlvmpipeCanvas");
  const std::size_t at = (static_cast<std::size_t>(y) * c.width + x) * 4;
  return {c.rgba8[at], c.rgba8[at + 1], c.rgba8[at + 2], c.rgba8[at + 3]};
}

WriteCounts llvmpipe_write_counts(int width, int height, std::span<const SceneTriangle> triangles,
                                  LlvmpipeCanvas::Viewport viewport) {
  LlvmpipeCanvas canvas(width, height, LlvmpipeCanvas::Pixels::write_counts, viewport);
  return canvas.write_counts(triangles);
}

}  // namespace tri
