#include "common/pixel_diagram.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "common/printable_text.hpp"

namespace tri {
namespace {

constexpr double title_height = 34;
constexpr double axis_room = 34;    // left of the grid, for the y pixel numbers
constexpr double bottom_room = 22;  // under the grid, for the x pixel numbers
constexpr double right_room = 16;
constexpr double legend_row = 22;
constexpr double legend_swatch = 16;
constexpr double char_width = 6.8;  // a generous estimate for 12-unit sans-serif text
constexpr double min_width = 380;

// Shortest decimal that reads back as the same double (locale-independent).
std::string number(double value) {
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return std::string(buffer.data(), result.ptr);
}

// SVG coordinates, rounded to 1/100 unit so the file stays small and stable.
std::string unit(double value) {
  double rounded = std::round(value * 100.0) / 100.0;
  if (rounded == 0) rounded = 0;  // no "-0"
  return number(rounded);
}

std::string hex(Color c) {
  return std::string(hex_color(c));
}

double text_width(const std::string& text, double size = 12) {
  // Count code points, not bytes, so "×" or "½" count once.
  double points = 0;
  for (const char ch : text) {
    if ((static_cast<unsigned char>(ch) & 0xC0) != 0x80) points += 1;
  }
  return points * char_width * size / 12.0;
}

// The step between numbered ticks that keeps labels at least min_gap units apart.
int tick_step(double cell, double min_gap) {
  for (const int step : {1, 2, 5, 10, 20, 50, 100, 200, 500, 1000, 2000, 5000}) {
    if (step * cell >= min_gap) return step;
  }
  return 10000;
}

std::string text_element(double x, double y, const std::string& text, const char* anchor,
                         Color color, double size, bool halo) {
  std::string out = "<text x=\"" + unit(x) + "\" y=\"" + unit(y) + "\" font-size=\"" + unit(size) +
                    "\" text-anchor=\"" + anchor + "\" fill=\"" + hex(color) + "\"";
  if (halo) out += " stroke=\"#ffffff\" stroke-width=\"3\" paint-order=\"stroke\"";
  return out + ">" + escape_xml(text) + "</text>\n";
}

std::string line_element(glm::dvec2 a, glm::dvec2 b, Color color, double width, bool dashed) {
  std::string out = "<line x1=\"" + unit(a.x) + "\" y1=\"" + unit(a.y) + "\" x2=\"" + unit(b.x) +
                    "\" y2=\"" + unit(b.y) + "\" stroke=\"" + hex(color) + "\" stroke-width=\"" +
                    unit(width) + "\" stroke-linecap=\"round\"";
  if (dashed) out += " stroke-dasharray=\"" + unit(3 * width) + " " + unit(2 * width) + "\"";
  return out + "/>\n";
}

}  // namespace

PixelDiagram::PixelDiagram(glm::ivec2 first, glm::ivec2 last, std::string title, double cell_size)
    : first_(first),
      last_(last),
      title_(std::move(title)),
      cell_(cell_size),
      centres_(cell_size >= 8) {
  if (last.x < first.x || last.y < first.y) {
    throw std::invalid_argument("a pixel diagram needs first <= last on both axes");
  }
  if (!(cell_size >= 1)) throw std::invalid_argument("a pixel diagram's cells must be >= 1 unit");
  const auto count = static_cast<std::size_t>(last.x - first.x + 1) *
                     static_cast<std::size_t>(last.y - first.y + 1);
  fills_.assign(count, diagram_colors::empty);
}

bool PixelDiagram::in_range(glm::ivec2 p) const noexcept {
  return p.x >= first_.x && p.x <= last_.x && p.y >= first_.y && p.y <= last_.y;
}

void PixelDiagram::fill(glm::ivec2 pixel, Color color) {
  if (!in_range(pixel)) return;
  const auto columns = static_cast<std::size_t>(last_.x - first_.x + 1);
  fills_[static_cast<std::size_t>(pixel.y - first_.y) * columns +
         static_cast<std::size_t>(pixel.x - first_.x)] = color;
}

void PixelDiagram::fill(std::span<const glm::ivec2> pixels, Color color) {
  for (const auto p : pixels) fill(p, color);
}

void PixelDiagram::fill_from(const Canvas& canvas, Color skip, glm::ivec2 origin) {
  for (int y = 0; y < canvas.height(); ++y) {
    for (int x = 0; x < canvas.width(); ++x) {
      const Color c = canvas.pixel(x, y);
      if (c != skip) fill(origin + glm::ivec2(x, y), c);
    }
  }
}

double PixelDiagram::grid_left() const noexcept {
  return axis_room;
}
double PixelDiagram::grid_top() const noexcept {
  return title_height;
}

glm::dvec2 PixelDiagram::to_svg(glm::dvec2 p) const noexcept {
  // Pixel first.x's square starts at the grid's left edge; y grows up in the picture.
  return {grid_left() + (p.x - (first_.x - 0.5)) * cell_,
          grid_top() + ((last_.y + 0.5) - p.y) * cell_};
}

std::string PixelDiagram::mark_markup(glm::dvec2 c, double size, PixelMark mark,
                                      Color color) const {
  const double stroke = std::max(1.5, size * 0.09);
  const double half = size / 2;
  switch (mark) {
    case PixelMark::ring:
      return "<circle cx=\"" + unit(c.x) + "\" cy=\"" + unit(c.y) + "\" r=\"" + unit(size * 0.33) +
             "\" fill=\"none\" stroke=\"" + hex(color) + "\" stroke-width=\"" + unit(stroke) +
             "\"/>\n";
    case PixelMark::cross: {
      const double d = size * 0.3;
      return line_element(c + glm::dvec2(-d, -d), c + glm::dvec2(d, d), color, stroke, false) +
             line_element(c + glm::dvec2(-d, d), c + glm::dvec2(d, -d), color, stroke, false);
    }
    case PixelMark::hatch: {
      // Lines x + y = k across the square, clipped to it by hand (no clip paths to collide).
      std::string out;
      const glm::dvec2 corner = c - glm::dvec2(half, half);
      for (int i = 1; i < 8; ++i) {
        const double k = size * i / 4.0;
        const glm::dvec2 a(std::max(0.0, k - size), std::min(k, size));
        const glm::dvec2 b(std::min(k, size), std::max(0.0, k - size));
        out += line_element(corner + a, corner + b, color, std::max(1.0, size * 0.05), false);
      }
      return out;
    }
    case PixelMark::square: {
      const double inset = stroke;
      return "<rect x=\"" + unit(c.x - half + inset) + "\" y=\"" + unit(c.y - half + inset) +
             "\" width=\"" + unit(size - 2 * inset) + "\" height=\"" + unit(size - 2 * inset) +
             "\" fill=\"none\" stroke=\"" + hex(color) + "\" stroke-width=\"" + unit(stroke * 1.5) +
             "\"/>\n";
    }
  }
  return {};
}

void PixelDiagram::mark(glm::ivec2 pixel, PixelMark mark, Color color) {
  if (!in_range(pixel)) return;
  marks_ += mark_markup(to_svg(glm::dvec2(pixel)), cell_, mark, color);
}

void PixelDiagram::pixel_text(glm::ivec2 pixel, std::string text, Color color) {
  if (!in_range(pixel)) return;
  const glm::dvec2 c = to_svg(glm::dvec2(pixel));
  const double size = std::clamp(cell_ * 0.5, 7.0, 16.0);
  marks_ += text_element(c.x, c.y + size * 0.36, text, "middle", color, size, false);
}

std::optional<std::array<glm::dvec2, 2>> clip_segment(glm::dvec2 a, glm::dvec2 b, glm::dvec2 lo,
                                                      glm::dvec2 hi) noexcept {
  // Liang–Barsky: the part of a + t (b - a), 0 <= t <= 1, on the inner side of all four sides.
  double t0 = 0, t1 = 1;
  const glm::dvec2 d = b - a;
  const double p[4] = {-d.x, d.x, -d.y, d.y};
  const double q[4] = {a.x - lo.x, hi.x - a.x, a.y - lo.y, hi.y - a.y};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0) {
      if (q[i] < 0) return std::nullopt;  // parallel to this side and outside it
      continue;
    }
    const double t = q[i] / p[i];
    if (p[i] < 0) {
      t0 = std::max(t0, t);
    } else {
      t1 = std::min(t1, t);
    }
    if (t0 > t1) return std::nullopt;
  }
  return std::array<glm::dvec2, 2>{a + t0 * d, a + t1 * d};
}

std::optional<std::array<glm::dvec2, 2>> clip_to_pixels(glm::dvec2 a, glm::dvec2 b,
                                                        glm::ivec2 first,
                                                        glm::ivec2 last) noexcept {
  return clip_segment(a, b, glm::dvec2(first) - 0.5, glm::dvec2(last) + 0.5);
}

void PixelDiagram::line(glm::dvec2 a, glm::dvec2 b, Color color, double width, bool dashed) {
  const auto visible = clip_to_pixels(a, b, first_, last_);
  if (!visible) return;
  geometry_ += line_element(to_svg((*visible)[0]), to_svg((*visible)[1]), color, width, dashed);
}

void PixelDiagram::frame(glm::ivec2 first, glm::ivec2 last, Color color, double width,
                         bool dashed) {
  const glm::dvec2 lo = glm::dvec2(first) - 0.5, hi = glm::dvec2(last) + 0.5;
  line(lo, {hi.x, lo.y}, color, width, dashed);
  line({hi.x, lo.y}, hi, color, width, dashed);
  line(hi, {lo.x, hi.y}, color, width, dashed);
  line({lo.x, hi.y}, lo, color, width, dashed);
}

void PixelDiagram::triangle(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, Color color, double width) {
  const glm::dvec2 lo = glm::dvec2(first_) - 0.5, hi = glm::dvec2(last_) + 0.5;
  const auto inside = [&](glm::dvec2 p) {
    return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y;
  };
  if (!(inside(a) && inside(b) && inside(c))) {
    // Partly outside: its edges, each cut to the grid.
    line(a, b, color, width);
    line(b, c, color, width);
    line(c, a, color, width);
    return;
  }
  const glm::dvec2 pa = to_svg(a), pb = to_svg(b), pc = to_svg(c);
  geometry_ += "<polygon points=\"" + unit(pa.x) + "," + unit(pa.y) + " " + unit(pb.x) + "," +
               unit(pb.y) + " " + unit(pc.x) + "," + unit(pc.y) + "\" fill=\"none\" stroke=\"" +
               hex(color) + "\" stroke-width=\"" + unit(width) + "\" stroke-linejoin=\"round\"/>\n";
}

void PixelDiagram::point(glm::dvec2 p, Color color, double radius) {
  const glm::dvec2 s = to_svg(p);
  labels_ += "<circle cx=\"" + unit(s.x) + "\" cy=\"" + unit(s.y) + "\" r=\"" + unit(radius) +
             "\" fill=\"" + hex(color) + "\" stroke=\"#ffffff\" stroke-width=\"1\"/>\n";
}

void PixelDiagram::label(glm::dvec2 p, std::string text, LabelPlace place, Color color) {
  const glm::dvec2 s = to_svg(p);
  constexpr double gap = 7, size = 12;
  double x = s.x, y = s.y;
  const char* anchor = "start";
  switch (place) {
    case LabelPlace::above_right:
      x += gap;
      y -= gap;
      break;
    case LabelPlace::above_left:
      x -= gap;
      y -= gap;
      anchor = "end";
      break;
    case LabelPlace::below_right:
      x += gap;
      y += gap + size * 0.8;
      break;
    case LabelPlace::below_left:
      x -= gap;
      y += gap + size * 0.8;
      anchor = "end";
      break;
    case LabelPlace::right:
      x += gap;
      y += size * 0.35;
      break;
    case LabelPlace::left:
      x -= gap;
      y += size * 0.35;
      anchor = "end";
      break;
  }
  labels_ += text_element(x, y, text, anchor, color, size, true);
}

void PixelDiagram::vertex(glm::dvec2 p, std::string name, LabelPlace place, Color color) {
  point(p, color, 4);
  label(p, name + " (" + number(p.x) + ", " + number(p.y) + ")", place, color);
}

void PixelDiagram::legend_fill(std::string text, Color color) {
  legend_.push_back({LegendEntry::Kind::fill, std::move(text), color});
}
void PixelDiagram::legend_mark(std::string text, PixelMark mark, Color color) {
  legend_.push_back({LegendEntry::Kind::mark, std::move(text), color, mark});
}
void PixelDiagram::legend_line(std::string text, Color color, bool dashed) {
  legend_.push_back({LegendEntry::Kind::line, std::move(text), color, PixelMark::ring, dashed});
}
void PixelDiagram::legend_point(std::string text, Color color, double radius) {
  legend_.push_back(
      {LegendEntry::Kind::point, std::move(text), color, PixelMark::ring, false, radius});
}
void PixelDiagram::legend_note(std::string text) {
  legend_.push_back({LegendEntry::Kind::note, std::move(text), diagram_colors::black});
}

glm::dvec2 PixelDiagram::size() const {
  const double grid_w = (last_.x - first_.x + 1) * cell_;
  const double grid_h = (last_.y - first_.y + 1) * cell_;
  double width = std::max(
      {grid_left() + grid_w + right_room, min_width, text_width(title_, 15) + 2 * right_room});
  for (const auto& entry : legend_) {
    if (entry.kind == LegendEntry::Kind::note) {
      width = std::max(width, text_width(entry.text) + 2 * right_room);
    }
  }
  const auto rows = static_cast<double>(legend_layout().size());
  const double legend_h = rows > 0 ? rows * legend_row + 8 : 0;
  return {width, grid_top() + grid_h + bottom_room + legend_h + 6};
}

std::vector<std::vector<const PixelDiagram::LegendEntry*>> PixelDiagram::legend_layout() const {
  // Entries flow left to right and wrap at the grid's width (at least min_width); a note takes
  // a row of its own.
  const double grid_w = (last_.x - first_.x + 1) * cell_;
  const double room = std::max(grid_left() + grid_w, min_width - right_room) - right_room;
  std::vector<std::vector<const LegendEntry*>> rows;
  double used = room + 1;
  for (const auto& entry : legend_) {
    const double w = legend_swatch + 8 + text_width(entry.text) + 18;
    if (entry.kind == LegendEntry::Kind::note) {
      rows.push_back({&entry});
      used = room + 1;
      continue;
    }
    if (used + w > room) {
      rows.emplace_back();
      used = 0;
    }
    rows.back().push_back(&entry);
    used += w;
  }
  return rows;
}

std::string PixelDiagram::pixels_markup() const {
  // One rectangle per run of equal colours along a row keeps dense diagrams small.
  std::string out;
  const int columns = last_.x - first_.x + 1;
  for (int y = first_.y; y <= last_.y; ++y) {
    const auto row = static_cast<std::size_t>(y - first_.y) * static_cast<std::size_t>(columns);
    int run_start = 0;
    for (int i = 1; i <= columns; ++i) {
      if (i < columns && fills_[row + i] == fills_[row + run_start]) continue;
      const Color c = fills_[row + run_start];
      if (c != diagram_colors::empty) {
        const glm::dvec2 top_left = to_svg(glm::dvec2(first_.x + run_start - 0.5, y + 0.5));
        out += "<rect x=\"" + unit(top_left.x) + "\" y=\"" + unit(top_left.y) + "\" width=\"" +
               unit((i - run_start) * cell_) + "\" height=\"" + unit(cell_) + "\" fill=\"" +
               hex(c) + "\"/>\n";
      }
      run_start = i;
    }
  }
  return out;
}

std::string PixelDiagram::grid_markup(const std::string& id_prefix) const {
  const double grid_w = (last_.x - first_.x + 1) * cell_;
  const double grid_h = (last_.y - first_.y + 1) * cell_;
  const std::string x = unit(grid_left()), y = unit(grid_top()), w = unit(grid_w), h = unit(grid_h),
                    c = unit(cell_);
  std::string out;
  // Grid lines and centre dots repeat every cell: one pattern each instead of one element per
  // pixel.
  if (cell_ >= 4) {
    out += "<defs><pattern id=\"" + id_prefix + "grid\" x=\"" + x + "\" y=\"" + y + "\" width=\"" +
           c + "\" height=\"" + c + "\" patternUnits=\"userSpaceOnUse\"><path d=\"M " + c +
           " 0 L 0 0 0 " + c + "\" fill=\"none\" stroke=\"#9a9a9a\" stroke-width=\"" +
           unit(cell_ >= 12 ? 1 : 0.5) + "\"/></pattern>";
    if (centres_) {
      out += "<pattern id=\"" + id_prefix + "centres\" x=\"" + x + "\" y=\"" + y + "\" width=\"" +
             c + "\" height=\"" + c + "\" patternUnits=\"userSpaceOnUse\"><circle cx=\"" +
             unit(cell_ / 2) + "\" cy=\"" + unit(cell_ / 2) + "\" r=\"" +
             unit(std::clamp(cell_ * 0.08, 1.2, 2.5)) +
             "\" fill=\"#303030\" stroke=\"#ffffff\" stroke-width=\"0.6\"/></pattern>";
    }
    out += "</defs>\n";
    out += "<rect x=\"" + x + "\" y=\"" + y + "\" width=\"" + w + "\" height=\"" + h +
           "\" fill=\"url(#" + id_prefix + "grid)\"/>\n";
    if (centres_) {
      out += "<rect x=\"" + x + "\" y=\"" + y + "\" width=\"" + w + "\" height=\"" + h +
             "\" fill=\"url(#" + id_prefix + "centres)\"/>\n";
    }
  }
  out += "<rect x=\"" + x + "\" y=\"" + y + "\" width=\"" + w + "\" height=\"" + h +
         "\" fill=\"none\" stroke=\"#606060\" stroke-width=\"1\"/>\n";
  return out;
}

std::string PixelDiagram::axes_markup() const {
  std::string out;
  // Room for the widest x label (about 6.5 units per digit at size 10) plus a gap.
  const auto digits = std::max(std::to_string(first_.x).size(), std::to_string(last_.x).size());
  const int step = tick_step(cell_, 6.5 * static_cast<double>(digits) + 10);
  const double grid_h = (last_.y - first_.y + 1) * cell_;
  for (int x = first_.x; x <= last_.x; ++x) {
    if (x % step != 0) continue;
    const glm::dvec2 s = to_svg(glm::dvec2(x, first_.y));
    out += text_element(s.x, grid_top() + grid_h + 14, std::to_string(x), "middle",
                        diagram_colors::dark_gray, 10, false);
  }
  for (int y = first_.y; y <= last_.y; ++y) {
    if (y % tick_step(cell_, 14) != 0) continue;
    const glm::dvec2 s = to_svg(glm::dvec2(first_.x, y));
    out += text_element(grid_left() - 5, s.y + 3.5, std::to_string(y), "end",
                        diagram_colors::dark_gray, 10, false);
  }
  return out;
}

std::string PixelDiagram::legend_markup() const {
  std::string out;
  const double grid_h = (last_.y - first_.y + 1) * cell_;
  double y = grid_top() + grid_h + bottom_room + 8;
  for (const auto& row : legend_layout()) {
    double x = right_room;
    for (const LegendEntry* entry : row) {
      const glm::dvec2 centre(x + legend_swatch / 2, y + legend_swatch / 2);
      switch (entry->kind) {
        case LegendEntry::Kind::fill:
          out += "<rect x=\"" + unit(x) + "\" y=\"" + unit(y) + "\" width=\"" +
                 unit(legend_swatch) + "\" height=\"" + unit(legend_swatch) + "\" fill=\"" +
                 hex(entry->color) + "\" stroke=\"#606060\" stroke-width=\"1\"/>\n";
          break;
        case LegendEntry::Kind::mark:
          out += "<rect x=\"" + unit(x) + "\" y=\"" + unit(y) + "\" width=\"" +
                 unit(legend_swatch) + "\" height=\"" + unit(legend_swatch) +
                 "\" fill=\"#ffffff\" stroke=\"#9a9a9a\" stroke-width=\"1\"/>\n";
          out += mark_markup(centre, legend_swatch, entry->mark, entry->color);
          break;
        case LegendEntry::Kind::line:
          out += line_element(centre - glm::dvec2(legend_swatch / 2, 0),
                              centre + glm::dvec2(legend_swatch / 2, 0), entry->color, 2.5,
                              entry->dashed);
          break;
        case LegendEntry::Kind::point:
          out += "<circle cx=\"" + unit(centre.x) + "\" cy=\"" + unit(centre.y) + "\" r=\"" +
                 unit(entry->radius) + "\" fill=\"" + hex(entry->color) +
                 "\" stroke=\"#ffffff\" stroke-width=\"1\"/>\n";
          break;
        case LegendEntry::Kind::note:
          out += text_element(x, y + 12, entry->text, "start", diagram_colors::black, 12, false);
          continue;
      }
      out += text_element(x + legend_swatch + 6, y + 12.5, entry->text, "start",
                          diagram_colors::black, 12, false);
      x += legend_swatch + 8 + text_width(entry->text) + 18;
    }
    y += legend_row;
  }
  return out;
}

std::string PixelDiagram::svg_elements(const std::string& id_prefix) const {
  const glm::dvec2 s = size();
  std::string out =
      "<rect width=\"" + unit(s.x) + "\" height=\"" + unit(s.y) + "\" fill=\"#ffffff\"/>\n";
  out += text_element(right_room, 22, title_, "start", diagram_colors::black, 15, false);
  out += pixels_markup();
  out += grid_markup(id_prefix);
  out += marks_;
  out += geometry_;
  out += labels_;
  out += axes_markup();
  out += legend_markup();
  return out;
}

std::string PixelDiagram::svg() const {
  const glm::dvec2 s = size();
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + unit(s.x) + "\" height=\"" +
         unit(s.y) + "\" viewBox=\"0 0 " + unit(s.x) + " " + unit(s.y) +
         "\" font-family=\"DejaVu Sans, Arial, sans-serif\">\n" + svg_elements("d-") + "</svg>\n";
}

std::string side_by_side(std::span<const PixelDiagram> panels, const std::string& title) {
  constexpr double gap = 12, top = 34;
  double width = gap, height = 0;
  for (const auto& panel : panels) {
    width += panel.size().x + gap;
    height = std::max(height, panel.size().y);
  }
  width = std::max(width, text_width(title, 15) + 2 * gap);
  height += top + gap;
  std::string out = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + unit(width) +
                    "\" height=\"" + unit(height) + "\" viewBox=\"0 0 " + unit(width) + " " +
                    unit(height) + "\" font-family=\"DejaVu Sans, Arial, sans-serif\">\n";
  out += "<rect width=\"" + unit(width) + "\" height=\"" + unit(height) + "\" fill=\"#ffffff\"/>\n";
  out += text_element(gap, 24, title, "start", diagram_colors::black, 16, false);
  double x = gap;
  for (std::size_t i = 0; i < panels.size(); ++i) {
    const glm::dvec2 s = panels[i].size();
    out += "<svg x=\"" + unit(x) + "\" y=\"" + unit(top) + "\" width=\"" + unit(s.x) +
           "\" height=\"" + unit(s.y) + "\">\n" +
           panels[i].svg_elements("p" + std::to_string(i) + "-") + "</svg>\n";
    x += s.x + gap;
  }
  return out + "</svg>\n";
}

}  // namespace tri
