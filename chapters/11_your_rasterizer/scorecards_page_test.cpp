#include "chapters/11_your_rasterizer/scorecards_page.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

#include "chapters/11_your_rasterizer/named_tests.hpp"
#include "measure/registry.hpp"

namespace {

const std::vector<tri::conformance::Scorecard>& cards() {
  static const auto graded = tri::ch11::book_scorecards(tri::registered_drawables());
  return graded;
}

const tri::conformance::Scorecard& card_of(const std::string& name) {
  const auto it = std::find_if(cards().begin(), cards().end(),
                               [&](const auto& c) { return c.rasterizer == name; });
  REQUIRE(it != cards().end());
  return *it;
}

}  // namespace

TEST_CASE("The scorecards page grades every registered fill that draws pixels, a row each",
          "[11_your_rasterizer][step4]") {
  const auto drawables = tri::registered_drawables();
  const auto drawing = std::count_if(drawables.begin(), drawables.end(),
                                     [](const tri::Drawable& d) { return d.colours != nullptr; });
  CHECK(cards().size() == static_cast<std::size_t>(drawing));
  const std::string page = tri::ch11::scorecards_markdown(cards());
  for (const auto& card : cards()) {
    CAPTURE(card.rasterizer);
    CHECK(page.find("| `" + card.rasterizer + "` |") != std::string::npos);
    CHECK(card.results.size() == tri::conformance::named_tests().size());
  }
  for (const auto& test : tri::conformance::named_tests()) {
    CHECK(page.find("- `" + test.name + "`: " + test.promise) != std::string::npos);
  }
}

TEST_CASE(
    "On the scorecards page the exact fills pass everything and each failure shows its "
    "diagram",
    "[11_your_rasterizer][step4]") {
  for (const char* exact : {"exact_oracle", "fixed_point_8", "fast_batched"}) {
    CAPTURE(exact);
    CHECK(card_of(exact).all_passed());
  }
  const auto& scanline = card_of("scanline_two_loops");
  REQUIRE_FALSE(scanline.all_passed());
  const std::string page = tri::ch11::scorecards_markdown(cards());
  for (const auto& r : scanline.results) {
    if (r.passed) continue;
    CAPTURE(r.test);
    CHECK(page.find("](" + tri::ch11::page_diagram_name(scanline, r) + ")\n") != std::string::npos);
    // The figure program saves the diagram under the stem, the page links the file.
    CHECK(tri::ch11::page_diagram_stem(scanline, r) == "scorecard_scanline_two_loops_" + r.test);
    CHECK(tri::ch11::page_diagram_name(scanline, r) ==
          tri::ch11::page_diagram_stem(scanline, r) + ".svg");
  }
}
