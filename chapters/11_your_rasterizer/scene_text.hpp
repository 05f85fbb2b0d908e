/// @file
/// A scene written in the text format of docs/DESIGN.md section 4, for a program graded through
/// --command; a NaN or infinite coordinate is written as `nan`, `inf` or `-inf`.
#pragma once

#include <string>

#include "common/scene.hpp"

namespace tri::conformance {

/// `canvas W H r g b`, then one `tri` line per triangle with its colour; coordinates in the
/// shortest decimals that read back exactly. Lines of the scene are left out (the suite has none).
std::string scene_text(const Scene& scene);

}  // namespace tri::conformance
