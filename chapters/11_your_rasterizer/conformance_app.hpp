/// @file
/// The conformance program (docs/DESIGN.md section 9): grades a registered algorithm (--algo) or
/// any program (--command) on the named tests and writes the scorecard (--out).
#pragma once

#include <ostream>
#include <span>

#include "chapters/11_your_rasterizer/scorecard.hpp"
#include "measure/drawable.hpp"

namespace tri::conformance {

/// Grades the rasterizer on every named test, prints the scorecard's rows on out, writes the
/// scorecard files into folder when one is given, and returns 0 when every test passed, else 1
/// with one line on err naming the failed tests.
int run_suite(const GradedRasterizer& rasterizer, TieRule rule,
              std::chrono::milliseconds time_limit,
              const std::optional<std::filesystem::path>& folder, std::ostream& out,
              std::ostream& err);

/// The program with the registry's drawables.
int run_conformance(int argc, const char* const* argv, std::ostream& out, std::ostream& err);

/// The program with these drawables (tests pass their own list).
int run_conformance(std::span<const Drawable> drawables, int argc, const char* const* argv,
                    std::ostream& out, std::ostream& err);

}  // namespace tri::conformance
