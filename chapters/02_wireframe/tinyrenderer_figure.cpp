#include "chapters/02_wireframe/tinyrenderer_figure.hpp"

#include "chapters/02_wireframe/example_triangles.hpp"
#include "common/figures.hpp"

namespace tri::ch02 {

PixelDiagram tinyrenderer_scene_diagram(const std::string& title) {
  PixelDiagram d({0, 0}, {tinyrenderer_image_size - 1, tinyrenderer_image_size - 1}, title, 3);
  d.show_centres(false);
  return d;
}

PixelDiagram tinyrenderer_fill_diagram(const std::string& title, const WholePixelFill& fill) {
  Canvas canvas(tinyrenderer_image_size, tinyrenderer_image_size);
  for (std::size_t i = 0; i < tinyrenderer_triangles.size(); ++i) {
    const auto& [a, b, c] = tinyrenderer_triangles[i].vertices;
    fill(canvas, a, b, c, tinyrenderer_figure_colors[i]);
  }
  PixelDiagram d = tinyrenderer_scene_diagram(title);
  d.fill_from(canvas, colors::black);
  for (std::size_t i = 0; i < tinyrenderer_triangles.size(); ++i) {
    const auto& [a, b, c] = tinyrenderer_triangles[i].vertices;
    d.triangle(glm::dvec2(a), glm::dvec2(b), glm::dvec2(c), diagram_colors::black, 1);
    const auto painted = painted_pixels(canvas, tinyrenderer_figure_colors[i]).size();
    d.legend_fill(std::string(tinyrenderer_names[i]) + " " + point_text(a) + " " + point_text(b) +
                      " " + point_text(c) + ": " + std::to_string(painted) + " pixels",
                  tinyrenderer_figure_colors[i]);
  }
  d.legend_line("ideal triangle edges", diagram_colors::black);
  return d;
}

void label_vertices(PixelDiagram& d, const std::array<glm::ivec2, 3>& v,
                    const std::array<LabelPlace, 3>& places) {
  const std::array<const char*, 3> names{"A", "B", "C"};
  for (std::size_t k = 0; k < 3; ++k) d.vertex(glm::dvec2(v[k]), names[k], places[k]);
}

}  // namespace tri::ch02
