/// @file
/// The hard-case page of the docs site (hard_cases.md): a legend, the matrix of every algorithm
/// on every case, and one section per case with its reason, its diagram and its results in words.
#pragma once

#include <string>
#include <vector>

#include "measure/hard_cases.hpp"

namespace tri::hard_cases {

/// One outcome in words, e.g. "26 extra pixels, 1 pixel drawn too often", "exact" or "refused".
std::string in_words(const Outcome& outcome);

/// One outcome as a short matrix cell, e.g. "x26 o1", "exact" or "refused" (the legend above
/// the matrix spells the letters out).
std::string cell(const Outcome& outcome);

/// The page as Markdown. Each case's section shows its diagram by file name (diagram_name +
/// ".svg", written next to the page). Deterministic.
std::string to_markdown(const std::vector<Outcome>& outcomes, const std::vector<HardCase>& cases);

}  // namespace tri::hard_cases
