#include "common/figures.hpp"

#include <iostream>
#include <stdexcept>

#include "common/cli.hpp"
#include "common/image_io.hpp"
#include "common/output_files.hpp"

namespace tri {

FigureWriter::FigureWriter(std::filesystem::path folder, std::ostream& log)
    : folder_(std::move(folder)), log_(log) {}

void FigureWriter::save_png(std::string_view name, const Canvas& canvas) {
  const auto path = folder_ / (std::string(name) + ".png");
  write_png(canvas, path);
  log_ << "wrote " << path.string() << "\n";
}

void FigureWriter::save_text(std::string_view name, std::string_view text) {
  const auto path = folder_ / std::string(name);
  write_file_safely(path, bytes_of_text(text));
  log_ << "wrote " << path.string() << "\n";
}

void FigureWriter::save_svg(std::string_view name, std::string_view svg) {
  save_text(std::string(name) + ".svg", svg);
}

std::string point_text(glm::ivec2 p) {
  return "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")";
}

std::vector<glm::ivec2> painted_pixels(const Canvas& canvas, Color color) {
  std::vector<glm::ivec2> pixels;
  for (int y = 0; y < canvas.height(); ++y) {
    for (int x = 0; x < canvas.width(); ++x) {
      if (canvas.pixel(x, y) == color) pixels.emplace_back(x, y);
    }
  }
  return pixels;
}

Canvas magnified(const Canvas& canvas, int factor) {
  if (factor < 1) throw std::invalid_argument("magnification factor must be at least 1");
  Canvas big(canvas.width() * factor, canvas.height() * factor);
  for (int y = 0; y < big.height(); ++y) {
    for (int x = 0; x < big.width(); ++x) big.put_pixel(x, y, canvas.pixel(x / factor, y / factor));
  }
  return big;
}

int run_chapter_program(int argc, const char* const* argv, std::string program,
                        std::string what_it_draws,
                        const std::function<void(FigureWriter& figures)>& render) {
  const CommandLine command_line(std::move(program), std::move(what_it_draws),
                                 {{"out", "DIR", "folder for the figures (default: out)"}});
  return run_command_line(command_line, argc, argv, std::cout, std::cerr,
                          [&](const CliArguments& args) {
                            const std::string folder = args.value_or("out", "out");
                            check_output_folder(folder);  // before any drawing
                            FigureWriter figures(folder, std::cout);
                            render(figures);
                            return 0;
                          });
}

int run_chapter_program(int argc, const char* const* argv, std::string program,
                        std::string what_it_draws, std::vector<SvgFigureFunction> figures) {
  what_it_draws += "\nThe chapter's README says what each figure shows.";
  return run_chapter_program(argc, argv, std::move(program), std::move(what_it_draws),
                             [&](FigureWriter& writer) {
                               for (const auto& draw : figures) {
                                 const SvgFigure figure = draw();
                                 writer.save_svg(figure.name, figure.svg);
                               }
                             });
}

}  // namespace tri
