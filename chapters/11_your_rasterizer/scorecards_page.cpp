#include "chapters/11_your_rasterizer/scorecards_page.hpp"

#include <algorithm>
#include <iterator>
#include <sstream>
#include <variant>

#include <glm/common.hpp>

#include "chapters/11_your_rasterizer/command_rasterizer.hpp"
#include "chapters/11_your_rasterizer/graded_rasterizer.hpp"
#include "chapters/11_your_rasterizer/grading.hpp"
#include "chapters/11_your_rasterizer/named_tests.hpp"
#include "chapters/11_your_rasterizer/tie_rule.hpp"

namespace tri::ch11 {

std::vector<conformance::Scorecard> book_scorecards(std::span<const Drawable> drawables) {
  const auto tests = conformance::named_tests();
  std::vector<conformance::Scorecard> cards;
  for (const Drawable& d : drawables) {
    if (d.colours == nullptr) continue;  // fractions of pixels: not what the suite grades
    const conformance::TieRule rule = conformance::declared_tie_rule(d.rule);
    cards.push_back(
        {std::string(d.name), rule,
         conformance::grade_all(tests, conformance::graded_algorithm(*d.colours), rule)});
  }
  return cards;
}

std::string page_diagram_stem(const conformance::Scorecard& card,
                              const conformance::TestResult& result) {
  return "scorecard_" + card.rasterizer + "_" + result.test;
}

std::string page_diagram_name(const conformance::Scorecard& card,
                              const conformance::TestResult& result) {
  return page_diagram_stem(card, result) + ".svg";
}

conformance::WrongCase page_case(const conformance::WrongCase& wrong, int side) {
  const std::vector<glm::ivec2>& any = wrong.missed.empty() ? wrong.extra : wrong.missed;
  if (any.empty()) return wrong;
  const glm::ivec2 low = any.front() - side / 2, high = low + (side - 1);
  const auto inside = [&](glm::ivec2 p) {
    return p.x >= low.x && p.y >= low.y && p.x <= high.x && p.y <= high.y;
  };
  const auto kept = [&](const std::vector<glm::ivec2>& pixels) {
    std::vector<glm::ivec2> out;
    std::copy_if(pixels.begin(), pixels.end(), std::back_inserter(out), inside);
    return out;
  };
  conformance::WrongCase cut = wrong;
  cut.missed = kept(wrong.missed);
  cut.extra = kept(wrong.extra);
  cut.doubled = kept(wrong.doubled);
  cut.scene.primitives.clear();
  for (const auto& primitive : wrong.scene.primitives) {
    const auto* t = std::get_if<SceneTriangle>(&primitive);
    if (t == nullptr) continue;
    glm::dvec2 t_low = t->vertices[0], t_high = t->vertices[0];
    for (const glm::dvec2 v : t->vertices) {
      t_low = glm::min(t_low, v);
      t_high = glm::max(t_high, v);
    }
    // A NaN vertex fails every comparison: such a triangle is never drawn, nor kept here.
    if (t_high.x >= low.x - 1 && t_high.y >= low.y - 1 && t_low.x <= high.x + 1 &&
        t_low.y <= high.y + 1) {
      cut.scene.primitives.push_back(*t);
    }
  }
  return cut;
}

namespace {

// One row per rasterizer, one column per test, and the list of what each test checks.
std::string scorecards_table(std::span<const conformance::Scorecard> cards) {
  std::ostringstream md;
  if (cards.empty()) return md.str();
  md << "| rasterizer | rule |";
  for (const auto& r : cards.front().results) md << " `" << r.test << "` |";
  md << "\n|---|---|";
  for (std::size_t i = 0; i < cards.front().results.size(); ++i) md << "---|";
  md << "\n";
  for (const conformance::Scorecard& card : cards) {
    md << "| `" << card.rasterizer << "` | " << conformance::tie_rule_name(card.rule) << " |";
    for (const conformance::TestResult& r : card.results)
      md << (r.passed ? " pass |" : " **fail** |");
    md << "\n";
  }
  md << "\nWhat each test checks:\n\n";
  for (const auto& r : cards.front().results) md << "- `" << r.test << "`: " << r.promise << "\n";
  // Images, not links: the site copies a page's images, and a reader sees every failure at once.
  for (const conformance::Scorecard& card : cards) {
    bool heading = false;
    for (const conformance::TestResult& r : card.results) {
      if (r.passed || !r.smallest_failure) continue;
      if (!heading) md << "\n## The failures of `" << card.rasterizer << "`\n";
      heading = true;
      md << "\n![" << card.rasterizer << " on " << r.test << ": " << r.smallest_failure->label
         << ", its wrong pixels marked](" << page_diagram_name(card, r) << ")\n";
    }
  }
  // A refused scene, a crash or a hang has no wrong pixels to draw: its reason is the story.
  bool any_without_diagram = false;
  for (const conformance::Scorecard& card : cards) {
    for (const conformance::TestResult& r : card.results) {
      if (r.passed || r.smallest_failure) continue;
      if (!any_without_diagram) md << "\nFailures without wrong pixels to show:\n\n";
      any_without_diagram = true;
      md << "- `" << card.rasterizer << "`, `" << r.test << "`: " << r.detail << "\n";
    }
  }
  return md.str();
}

}  // namespace

std::string scorecards_markdown(std::span<const conformance::Scorecard> cards) {
  return "# Scorecards <!-- doxygen: {#scorecards} -->\n\n"
         "Every rasterizer of the book that draws pixels, graded by the conformance suite "
         "(chapter 11) under the tie rule it declares (top-left for those that declare no exact "
         "rule, so their errors show). Below the table, each failed test shows the pixel diagram "
         "of its smallest failing case: missed pixels, extra pixels and pixels drawn twice, marked "
         "over the ideal triangles. This page is written by `11_your_rasterizer --out`; where the "
         "site is built "
         "with the "
         "peers of chapter 10, their scorecards are on a page of their own.\n\n" +
         scorecards_table(cards);
}

std::vector<conformance::Scorecard> peer_scorecards(std::span<const ExternalPeer> peers,
                                                    const std::string& adapter) {
  const auto tests = conformance::named_tests();
  std::vector<conformance::Scorecard> cards;
  for (const ExternalPeer& peer : peers) {
    const conformance::TieRule rule = conformance::declared_tie_rule(peer.rule);
    const std::string command =
        adapter + " --peer " + std::string(peer.name) + " --scene {scene} --counts {counts}";
    cards.push_back({std::string(peer.name), rule,
                     conformance::grade_all(tests, conformance::graded_command(command), rule)});
  }
  return cards;
}

std::string peer_scorecards_markdown(std::span<const conformance::Scorecard> cards,
                                     const std::string& status) {
  return "# Scorecards of the peers <!-- doxygen: {#scorecards_peers} -->\n\n"
         "The rasterizers from outside the book that chapter 10 measures, graded by the same "
         "suite as [the book's own](scorecards.md), each through the `--command` protocol by a "
         "small adapter (`tools/peer_rasterizer`) and under the tie rule it declares. A scene "
         "beyond a library's fixed-point range is refused with a message, and the test that "
         "holds it fails with that reason. Peers of this build: " +
         status + ".\n\n" + scorecards_table(cards);
}

}  // namespace tri::ch11
