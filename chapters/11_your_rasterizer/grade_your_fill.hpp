/// @file
/// Grading the learner's fill: the conformance suite on your_fill, its scorecard written, and a
/// first hint when the fill draws nothing yet.
#pragma once

#include <filesystem>
#include <ostream>

#include "chapters/11_your_rasterizer/graded_rasterizer.hpp"
#include "chapters/11_your_rasterizer/tie_rule.hpp"

namespace tri::ch11 {

/// Whether the fill writes at least one pixel of a triangle that covers 40 pixel centres.
bool draws_anything(const conformance::FillFunction& fill);

/// Grades `fill` (named `name`) under `rule` on every named test, prints the rows on out and
/// writes the scorecard into folder; when the fill draws nothing at all, says on err what to do
/// first. 0 when every test passes, else 1.
int grade_fill(const std::string& name, const conformance::FillFunction& fill,
               conformance::TieRule rule, const std::filesystem::path& folder, std::ostream& out,
               std::ostream& err);

/// grade_fill on your_fill.
int grade_your_fill(conformance::TieRule rule, const std::filesystem::path& folder,
                    std::ostream& out, std::ostream& err);

}  // namespace tri::ch11
