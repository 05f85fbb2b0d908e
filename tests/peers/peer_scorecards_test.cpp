// The peers graded by chapter 11's suite through their adapter (tools/peer_rasterizer), as the
// site's page of their scorecards is made.
#include <catch2/catch.hpp>

#include <span>
#include <string>

#include "chapters/11_your_rasterizer/scorecards_page.hpp"
#include "measure/peers/library_peers.hpp"

#if TUTORIAL_WITH_PIXMAN
TEST_CASE("pixman graded through its adapter passes every test but those beyond its 16.16 range",
          "[peers][pixman][conformance]") {
  const tri::ExternalPeer pixman = tri::pixman_peer();
  const auto cards = tri::ch11::peer_scorecards(std::span(&pixman, 1), PEER_RASTERIZER);
  REQUIRE(cards.size() == 1);
  CHECK(cards.front().failed_tests() == "hard_cases, range_32768, range_2_30");
  const std::string page = tri::ch11::peer_scorecards_markdown(cards, "pixman: measured");
  CHECK_THAT(page, Catch::Contains("| `pixman_a1` | top-left |") &&
                       Catch::Contains("Failures without wrong pixels to show") &&
                       Catch::Contains("pixman cannot draw this scene"));
}
#endif
