/// @file
/// The raster tool: renders any scene with any registered algorithm
/// (@ref design_command_line "docs/DESIGN.md section 9").
#pragma once

#include <ostream>
#include <span>

#include "measure/drawable.hpp"

namespace tri {

/// The whole `raster` program, in-process so tests can call it:
///   raster --list
///   raster --algo NAME --scene FILE [--out FILE.png] [--counts FILE.pgm]
///   raster --algo NAME --scene FILE --coverage FILE.pgm   (an algorithm of rule area)
///   raster --algo NAME --scene FILE --bench N
/// Returns the exit status; errors are one line on err and leave no output file behind.
/// Draws with the registry's drawables (registered_drawables).
int run_raster(int argc, const char* const* argv, std::ostream& out, std::ostream& err);

/// The same program over any list of drawables: what each can do is what it declares.
int run_raster(std::span<const Drawable> drawables, int argc, const char* const* argv,
               std::ostream& out, std::ostream& err);

}  // namespace tri
