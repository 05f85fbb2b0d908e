/// @file
/// Pixel diagrams: a zoomed pixel grid drawn as SVG, with the ideal geometry over it.
///
/// Every figure that argues about individual pixels is one of these (docs/DESIGN.md, figures):
/// pixel squares coloured by category, a dot on every pixel centre (the sample point), the exact
/// segments and triangle edges drawn from the real vertex coordinates, vertex labels, marks on
/// the pixels the text talks about, pixel numbers on the axes, and a title and a legend inside
/// the image. The chapters only say what to draw; this writer decides how it looks.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>

#include "common/canvas.hpp"
#include "common/color.hpp"

namespace tri {

/// Colours for diagrams: the Okabe–Ito palette, which stays distinct for colour-blind readers,
/// plus the neutral tones of the grid.
namespace diagram_colors {
inline constexpr Color orange{230, 159, 0, 255};
inline constexpr Color sky_blue{86, 180, 233, 255};
inline constexpr Color bluish_green{0, 158, 115, 255};
inline constexpr Color yellow{240, 228, 66, 255};
inline constexpr Color blue{0, 114, 178, 255};
inline constexpr Color vermillion{213, 94, 0, 255};
inline constexpr Color purple{204, 121, 167, 255};
inline constexpr Color black{0, 0, 0, 255};
/// A pixel that nothing covers.
inline constexpr Color empty{255, 255, 255, 255};
/// A pixel drawn by the algorithm (the plain "covered" category).
inline constexpr Color covered{160, 160, 160, 255};
inline constexpr Color light_gray{220, 220, 220, 255};
inline constexpr Color dark_gray{90, 90, 90, 255};
}  // namespace diagram_colors

/// A colour as SVG writes it, "#rrggbb", made at compile time, so that plots written as SVG text
/// take their colours from the palette above instead of a copy of it.
struct HexColor {
  std::array<char, 8> text{};  ///< "#rrggbb" and a terminating zero

  constexpr operator const char*() const noexcept { return text.data(); }
  constexpr operator std::string_view() const noexcept { return {text.data(), 7}; }
};

/// `color` as "#rrggbb" (its alpha is not written).
constexpr HexColor hex_color(Color color) noexcept {
  constexpr char digits[] = "0123456789abcdef";
  HexColor out;
  out.text[0] = '#';
  const int channels[3] = {color.x, color.y, color.z};  // r, g, b: glm's constexpr names
  for (int i = 0; i < 3; ++i) {
    out.text[static_cast<std::size_t>(1 + 2 * i)] = digits[channels[i] / 16];
    out.text[static_cast<std::size_t>(2 + 2 * i)] = digits[channels[i] % 16];
  }
  return out;
}

/// A symbol drawn on one pixel to point the reader at it.
enum class PixelMark {
  ring,   ///< a circle around the centre (e.g. a tie: a centre exactly on an edge)
  cross,  ///< an X over the pixel (e.g. a missed or a wrong pixel)
  hatch,  ///< diagonal hatching over the whole square (e.g. drawn twice)
  square  ///< a thick outline of the square (e.g. the pixel the text names)
};

/// Where a label sits relative to the point it names.
enum class LabelPlace { above_right, above_left, below_right, below_left, right, left };

/// A zoomed pixel grid with the ideal geometry over it, written as a standalone SVG document.
///
/// Coordinates are the tutorial's: pixel units, x right, y up, integer coordinates are pixel
/// centres, so pixel (i, j) is the square [i - 1/2, i + 1/2] x [j - 1/2, j + 1/2]. The diagram
/// shows the pixels from `first` to `last`, both included. Output is deterministic (same calls,
/// same bytes), so figures can be compared byte for byte.
class PixelDiagram {
 public:
  /// A diagram of pixels first.x..last.x by first.y..last.y, each a cell_size x cell_size square
  /// in SVG units, titled with one line of text. Throws std::invalid_argument for an empty range
  /// or a cell size below 1.
  PixelDiagram(glm::ivec2 first, glm::ivec2 last, std::string title, double cell_size = 24);

  /// Fills one pixel's square (a later fill replaces an earlier one; pixels outside the range
  /// are ignored).
  void fill(glm::ivec2 pixel, Color color);
  /// Fills every listed pixel.
  void fill(std::span<const glm::ivec2> pixels, Color color);
  /// Copies the colours of a canvas, whose pixel (0, 0) is the diagram's pixel `origin`; canvas
  /// pixels of colour `skip` are left as they are.
  void fill_from(const Canvas& canvas, Color skip, glm::ivec2 origin = {0, 0});
  /// Marks one pixel with a symbol.
  void mark(glm::ivec2 pixel, PixelMark mark, Color color = diagram_colors::black);
  /// Writes a short text (a count, a letter) in the middle of a pixel.
  void pixel_text(glm::ivec2 pixel, std::string text, Color color = diagram_colors::black);

  /// A straight segment of the ideal geometry, in pixel coordinates, cut to the diagram's pixels
  /// (so a far-away vertex still gives the right direction inside the grid).
  void line(glm::dvec2 a, glm::dvec2 b, Color color, double width = 2, bool dashed = false);
  /// The outer border of the squares of pixels first..last (a region the text points at).
  void frame(glm::ivec2 first, glm::ivec2 last, Color color, double width = 1.5,
             bool dashed = false);
  /// The three edges of a triangle, cut to the diagram's pixels.
  void triangle(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, Color color, double width = 2);
  /// A filled dot at a point, radius in SVG units.
  void point(glm::dvec2 p, Color color, double radius = 4);
  /// A text next to a point.
  void label(glm::dvec2 p, std::string text, LabelPlace place = LabelPlace::above_right,
             Color color = diagram_colors::black);
  /// A vertex: a dot and the label "name (x, y)" with its exact coordinates.
  void vertex(glm::dvec2 p, std::string name, LabelPlace place = LabelPlace::above_right,
              Color color = diagram_colors::black);

  /// Legend entries, shown below the grid in the order they were added.
  void legend_fill(std::string text, Color color);
  void legend_mark(std::string text, PixelMark mark, Color color = diagram_colors::black);
  void legend_line(std::string text, Color color, bool dashed = false);
  /// A dot as point() draws it, radius in SVG units (e.g. a sample point).
  void legend_point(std::string text, Color color, double radius = 4);
  /// A line of plain text under the legend.
  void legend_note(std::string text);

  /// Hides the pixel-centre dots (for dense whole-scene figures); they are shown by default when
  /// a cell is at least 8 units wide.
  void show_centres(bool show) noexcept { centres_ = show; }

  /// The whole diagram as an SVG document.
  std::string svg() const;

  /// Width and height of the document in SVG units.
  glm::dvec2 size() const;

  /// The diagram's SVG elements without the enclosing document; ids start with id_prefix, so
  /// several diagrams can share one document (side_by_side).
  std::string svg_elements(const std::string& id_prefix) const;

 private:
  struct LegendEntry {
    enum class Kind { fill, mark, line, note, point } kind;
    std::string text;
    Color color;
    PixelMark mark = PixelMark::ring;
    bool dashed = false;
    double radius = 4;
  };

  bool in_range(glm::ivec2 pixel) const noexcept;
  glm::dvec2 to_svg(glm::dvec2 p) const noexcept;
  std::string mark_markup(glm::dvec2 centre, double size, PixelMark mark, Color color) const;
  std::vector<std::vector<const LegendEntry*>> legend_layout() const;
  double grid_left() const noexcept;
  double grid_top() const noexcept;
  std::string pixels_markup() const;
  std::string grid_markup(const std::string& id_prefix) const;
  std::string axes_markup() const;
  std::string legend_markup() const;

  glm::ivec2 first_, last_;
  std::string title_;
  double cell_;
  bool centres_;
  std::vector<Color> fills_;  // one per pixel of the range, row by row from first.y up
  std::string marks_;
  std::string geometry_;
  std::string labels_;
  std::vector<LegendEntry> legend_;
};

/// The part of segment ab inside the box [lo, hi], or nothing when it misses the box.
std::optional<std::array<glm::dvec2, 2>> clip_segment(glm::dvec2 a, glm::dvec2 b, glm::dvec2 lo,
                                                      glm::dvec2 hi) noexcept;

/// The part of segment ab over the squares of pixels first..last, i.e. inside the box
/// [first - 1/2, last + 1/2]: what a diagram of those pixels shows of it.
std::optional<std::array<glm::dvec2, 2>> clip_to_pixels(glm::dvec2 a, glm::dvec2 b,
                                                        glm::ivec2 first, glm::ivec2 last) noexcept;

/// Several diagrams side by side in one SVG document, top-aligned, with one title above them.
std::string side_by_side(std::span<const PixelDiagram> panels, const std::string& title);

}  // namespace tri
