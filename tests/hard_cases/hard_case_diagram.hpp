/// @file
/// One pixel diagram per hard case for the hard-case page: the case's triangles over the pixel
/// grid, the pixels the exact oracle covers, and every pixel centre that lies exactly on an edge.
#pragma once

#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "measure/hard_cases.hpp"

namespace tri::hard_cases {

/// A corner of the case's triangles with its name: "A", or "A = B" where vertices coincide.
struct NamedVertex {
  std::string name;
  glm::dvec2 position;
};

/// The case's distinct vertices named A, B, C, ... in scene order (coinciding vertices share one
/// entry); empty for cases of more than two triangles (fans and meshes).
std::vector<NamedVertex> named_vertices(const HardCase& hard_case);

/// A coordinate pair as the page and the diagram write it, e.g. "(12.75, 6.125)" or
/// "(nan, 20)": the shortest decimals that read back exactly.
std::string coordinates(glm::dvec2 p);

/// Whether a vertex of the case lies outside the canvas (or is not finite): its diagram then
/// shows the whole canvas with the part of the triangles inside it, and the page names the real
/// coordinates.
bool reaches_beyond_canvas(const HardCase& hard_case);

/// The name of the case's diagram without ".svg", e.g. "hard_case_fan_integer".
std::string diagram_name(const HardCase& hard_case);

/// The case's diagram as an SVG document (tri::PixelDiagram): the pixels around its triangles,
/// or the whole canvas when it reaches beyond it. Deterministic.
std::string diagram_svg(const HardCase& hard_case);

}  // namespace tri::hard_cases
