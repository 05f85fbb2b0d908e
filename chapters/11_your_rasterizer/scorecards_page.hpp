/// @file
/// The scorecards of the book's own rasterizers: every registered algorithm that draws pixels
/// graded on the conformance suite under the rule it declares, one row per algorithm, one column
/// per test, each failure linked to the pixel diagram of its smallest failing case.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "chapters/11_your_rasterizer/grading.hpp"
#include "chapters/11_your_rasterizer/scorecard.hpp"
#include "measure/drawable.hpp"
#include "measure/peers/peer.hpp"

namespace tri::ch11 {

/// The scorecard of every drawable that draws colours (rule area left out), in registry order.
std::vector<conformance::Scorecard> book_scorecards(std::span<const Drawable> drawables);

/// The stem of one algorithm's failure diagram on the page: "scorecard_NAME_TEST" (what a
/// FigureWriter, which adds ".svg", is given).
std::string page_diagram_stem(const conformance::Scorecard& card,
                              const conformance::TestResult& result);

/// The file name of one algorithm's failure diagram on the page: "scorecard_NAME_TEST.svg".
std::string page_diagram_name(const conformance::Scorecard& card,
                              const conformance::TestResult& result);

/// A failing case cut down for the page: the wrong pixels within a square of `side` pixels around
/// the first wrong one, and the triangles that reach into it, so every diagram stays small.
conformance::WrongCase page_case(const conformance::WrongCase& wrong, int side);

/// The page (docs/figures/scorecards.md, on the site): the table and what each test checks.
std::string scorecards_markdown(std::span<const conformance::Scorecard> cards);

/// The scorecard of every external peer, each graded through the --command protocol by
/// `adapter` (tools/peer_rasterizer) under the rule it declares.
std::vector<conformance::Scorecard> peer_scorecards(std::span<const ExternalPeer> peers,
                                                    const std::string& adapter);

/// The site's page of the peers' scorecards (scorecards_peers.md), built where the peers are:
/// the table, what each test checks, and `status`, the line that says which peers were built.
std::string peer_scorecards_markdown(std::span<const conformance::Scorecard> cards,
                                     const std::string& status);

}  // namespace tri::ch11
