#pragma once
/// @file
/// No measured number typed by hand: the Markdown files that quote measurements (the top-level
/// README and the READMEs of chapters 08, 09 and 10) may hold a time, a rate, a ratio of them, a
/// share or a memory size only inside a measured marker or a measured table (measured.hpp).
///
/// Measured-looking is a number directly followed by `×` or `x` (3.2×, not 8×8, 8x8 or 4 × 4),
/// or by a unit of time, rate or memory (ns, µs, ms, s after a space (not the 1990s), seconds,
/// minutes, Mpix/s, Mpixel/s, tris/s, M tris/s, Mtri/s, GB/s, MiB), or by `% of` a speed, time or
/// ceiling, or by `times faster`; and a table whose header names such a unit. Fenced blocks, code
/// spans, HTML comments and link targets are not prose.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tools/listings/listings.hpp"

namespace tri::listings {

/// True for the Markdown files that must hold no measured number outside markers.
bool quotes_measurements(std::string_view name);

/// The first measured-looking text of one line of prose (already without code spans), if any.
std::optional<std::string> measured_looking(std::string_view prose);

/// Adds a problem for every line of `lines` (a Markdown file) that holds a measured-looking
/// number outside markers, fenced blocks, code spans and measured tables.
void find_unmarked_measurements(const std::string& name, const std::vector<std::string>& lines,
                                std::vector<Problem>& problems);

}  // namespace tri::listings
