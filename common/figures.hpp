/// @file
/// What every chapter executable shares: the --help/--out command line and saving figures.
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>

#include "common/canvas.hpp"
#include "common/color.hpp"

namespace tri {

/// Saves a chapter's figures into one folder and says where each went.
class FigureWriter {
 public:
  FigureWriter(std::filesystem::path folder, std::ostream& log);

  /// Writes folder/name.png (atomically) and logs its path.
  void save_png(std::string_view name, const Canvas& canvas);
  /// Writes folder/name.svg (a pixel diagram or any SVG document) and logs its path.
  void save_svg(std::string_view name, std::string_view svg);
  /// Writes folder/name (any text, e.g. a Markdown table) and logs its path.
  void save_text(std::string_view name, std::string_view text);

 private:
  std::filesystem::path folder_;
  std::ostream& log_;
};

/// "(x, y)": a pixel's coordinates as the figures' labels and notes write them.
std::string point_text(glm::ivec2 p);

/// The pixels of a canvas painted in `color`, bottom row first, left to right.
std::vector<glm::ivec2> painted_pixels(const Canvas& canvas, Color color);

/// A copy of the canvas with every pixel blown up to a factor×factor square, so single pixels
/// are visible in the figures (factor >= 1).
Canvas magnified(const Canvas& canvas, int factor);

/// One figure as a chapter draws it: the file name it is saved under (without ".svg") and the
/// SVG document. A figure function returns it, so the name stands beside the drawing code.
struct SvgFigure {
  std::string name;
  std::string svg;
};

/// A function that draws one of a chapter's figures.
using SvgFigureFunction = std::function<SvgFigure()>;

/// The main() of a chapter executable: parses --help and --out DIR (default "out"), then calls
/// render with a FigureWriter on that folder. Returns the process exit status.
int run_chapter_program(int argc, const char* const* argv, std::string program,
                        std::string what_it_draws,
                        const std::function<void(FigureWriter& figures)>& render);

/// The same for a chapter whose figures are all SVG diagrams: draws each in order and saves it
/// as folder/NAME.svg. The help text adds that the chapter's README says what each shows.
int run_chapter_program(int argc, const char* const* argv, std::string program,
                        std::string what_it_draws, std::vector<SvgFigureFunction> figures);

}  // namespace tri
