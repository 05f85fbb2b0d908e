// Chapter 11's program: grades your fill (your_fill.cpp) on the conformance suite (--grade), and
// writes the chapter's figures (--out): the scorecards of the book's own rasterizers.
#include <chrono>
#include <filesystem>
#include <iostream>
#include <span>
#include <string>

#include "chapters/11_your_rasterizer/failure_diagram.hpp"
#include "chapters/11_your_rasterizer/grade_your_fill.hpp"
#include "chapters/11_your_rasterizer/scorecards_page.hpp"
#include "chapters/11_your_rasterizer/tie_rule.hpp"
#include "common/cli.hpp"
#include "common/figures.hpp"
#include "measure/peers/external_peers.hpp"
#include "measure/registry.hpp"

namespace {

// The diagram of each failed test's smallest case, cut to 16 pixels around its first wrong pixel.
void save_diagrams(tri::FigureWriter& figures, std::span<const tri::conformance::Scorecard> cards) {
  for (const auto& card : cards) {
    for (const auto& r : card.results) {
      if (r.passed || !r.smallest_failure) continue;
      figures.save_svg(tri::ch11::page_diagram_stem(card, r),
                       tri::conformance::failure_diagram_svg(
                           tri::ch11::page_case(*r.smallest_failure, 16),
                           card.rasterizer + ", " + r.test + ": " + r.smallest_failure->label));
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  const tri::CommandLine command_line(
      "11_your_rasterizer",
      "Chapter 11, your rasterizer. --grade DIR grades your_fill (chapters/11_your_rasterizer/\n"
      "your_fill.cpp) on the conformance suite and writes its scorecard into DIR; --out DIR\n"
      "writes the chapter's figures: scorecards.md, the scorecards of every rasterizer of the\n"
      "book, and the diagram of each failure (scorecard_NAME_TEST.svg).",
      {{"grade", "DIR", "grade your_fill and write its scorecard (scorecard.md, .csv, diagrams)"},
       {"rule", "top-left|bottom-left|any",
        "the tie rule your fill is graded under (default top-left)"},
       {"out", "DIR", "write the book's scorecards page and its diagrams (default out)"},
       {"peers-out", "DIR", "write the peers' scorecards page (scorecards_peers.md) and diagrams"},
       {"adapter", "PROGRAM", "with --peers-out: the peers' adapter (tools/peer_rasterizer)"}});
  return tri::run_command_line(
      command_line, argc, argv, std::cout, std::cerr, [&](const tri::CliArguments& args) {
        if (const auto folder = args.value("grade")) {
          const std::string rule_name = args.value_or("rule", "top-left");
          const auto rule = tri::conformance::parse_tie_rule(rule_name);
          if (!rule)
            throw tri::UsageError("--rule takes top-left, bottom-left or any, not " + rule_name);
          return tri::ch11::grade_your_fill(*rule, std::filesystem::path(*folder), std::cout,
                                            std::cerr);
        }
        if (args.has("rule")) throw tri::UsageError("--rule goes with --grade");
        if (const auto folder = args.value("peers-out")) {
          const auto adapter = args.value("adapter");
          if (!adapter) throw tri::UsageError("--peers-out needs --adapter PROGRAM");
          if (args.has("out")) throw tri::UsageError("--peers-out and --out write different pages");
          tri::FigureWriter figures(*folder, std::cout);
          const auto peers = tri::external_peers();
          const auto cards = tri::ch11::peer_scorecards(peers, *adapter);
          save_diagrams(figures, cards);
          figures.save_text("scorecards_peers.md", tri::ch11::peer_scorecards_markdown(
                                                       cards, tri::external_peer_status(peers)));
          return tri::exit_success;
        }
        if (args.has("adapter")) throw tri::UsageError("--adapter goes with --peers-out");
        tri::FigureWriter figures(args.value_or("out", "out"), std::cout);
        const auto cards = tri::ch11::book_scorecards(tri::registered_drawables());
        save_diagrams(figures, cards);
        figures.save_text("scorecards.md", tri::ch11::scorecards_markdown(cards));
        return tri::exit_success;
      });
}
