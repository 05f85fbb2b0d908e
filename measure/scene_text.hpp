/// @file
/// A scene written in the text format of docs/DESIGN.md section 4, for a program that reads scene
/// files (one graded through --command, `raster` timed by the report); a NaN or infinite
/// coordinate is written as `nan`, `inf` or `-inf`.
#pragma once

#include <filesystem>
#include <string>

#include "common/scene.hpp"

namespace tri {

/// `canvas W H r g b`, then one `tri` line per triangle with its colour; coordinates in the
/// shortest decimals that read back exactly. Lines of the scene are left out (the
/// suites have none).
std::string scene_text(const Scene& scene);

/// Writes scene_text(scene) to the file, replacing it; throws std::runtime_error when it cannot.
void write_scene_file(const std::filesystem::path& path, const Scene& scene);

}  // namespace tri
