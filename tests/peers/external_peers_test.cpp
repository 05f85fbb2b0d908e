#include "measure/peers/external_peers.hpp"

#include <catch2/catch.hpp>
#include <iterator>
#include <regex>
#include <set>
#include <string>
#include <string_view>

#include "measure/peers/library_peers.hpp"
#include "measure/registry.hpp"
#include "tests/peers/peer_test_support.hpp"

TEST_CASE("External peers have their own names, filed under 'external'",
          "[peers][external_peers]") {
  const auto drawables = tri::registered_drawables();
  std::set<std::string_view> names;
  const auto check_description = [&](const tri::Drawable& peer) {
    CAPTURE(peer.name);
    CHECK(names.insert(peer.name).second);
    CHECK(tri::find_named(drawables, peer.name) == nullptr);  // --only can tell them apart
    CHECK(peer.chapter == "external");
    CHECK(!peer.summary.empty());
    CHECK(peer.colours == nullptr);  // a peer draws into its own buffer, never a Canvas
    CHECK(peer.coverage == nullptr);
  };
  for (const tri::ExternalPeer& peer : tri::external_peers()) {
    check_description(peer);
    CHECK(peer.outputs == tri::Outputs{tri::Output::counts});
    CHECK(peer.rule != tri::CoverageRule::area);
    CHECK(static_cast<bool>(peer.measure));
  }
  for (const tri::CoveragePeer& peer : tri::coverage_peers()) {
    check_description(peer);
    CHECK(peer.outputs == tri::coverage_outputs);
    CHECK(peer.rule == tri::CoverageRule::area);
    CHECK(static_cast<bool>(peer.measure));
  }
}

TEST_CASE("The Machine line says which peers were measured, or why each was not",
          "[peers][external_peers]") {
  const auto peers = tri::external_peers();
  const std::string all = tri::external_peer_status(peers);
  const std::string none = tri::external_peer_status({});
  CAPTURE(all, none);
  const auto says = [](const std::string& line, const std::string& what) {
    return line.find(what) != std::string::npos;
  };
  struct Library {
    std::string name;
    bool built;
    std::string peers;
  };
  for (const Library& library :
       {Library{"Mesa llvmpipe", TUTORIAL_WITH_OSMESA != 0,
                "(mesa_llvmpipe_1_thread, mesa_llvmpipe_default)"},
        Library{"pixman", TUTORIAL_WITH_PIXMAN != 0, "(pixman_a1)"},
        Library{"cairo", TUTORIAL_WITH_CAIRO != 0, "(cairo_no_antialias)"}}) {
    CAPTURE(library.name);
    if (library.built) {
      CHECK(says(all, library.name + ": measured " + library.peers));
      CHECK(says(none, library.name + ": built, not selected by --only"));
    } else {
      CHECK(says(all, library.name + ": not built ("));
    }
  }
}

TEST_CASE("The snapshot's peers line names the release of each library this build measures",
          "[peers][external_peers]") {
  const std::string versions = tri::peer_versions();
  CAPTURE(versions);
  const std::regex release_of(R"((Mesa|pixman|cairo|FreeType) \d+\.\d+\.\d+)");
  const std::size_t built = (TUTORIAL_WITH_OSMESA != 0) + (TUTORIAL_WITH_PIXMAN != 0) +
                            (TUTORIAL_WITH_CAIRO != 0) + (TUTORIAL_WITH_FREETYPE != 0);
  const auto found = std::distance(
      std::sregex_iterator(versions.begin(), versions.end(), release_of), std::sregex_iterator());
  CHECK(static_cast<std::size_t>(found) == built);
  CHECK((versions.find("Mesa ") != std::string::npos) == (TUTORIAL_WITH_OSMESA != 0));
  CHECK((versions.find("pixman ") != std::string::npos) == (TUTORIAL_WITH_PIXMAN != 0));
  CHECK((versions.find("cairo ") != std::string::npos) == (TUTORIAL_WITH_CAIRO != 0));
  CHECK((versions.find("FreeType ") != std::string::npos) == (TUTORIAL_WITH_FREETYPE != 0));
  if (built == 0) CHECK(versions == "none");
}

namespace {

// A triangle reaching x = far_x on an 8x8 canvas: the library must refuse the scene with a message
// naming itself and its limit, never draw it with wrapped-around fixed-point coordinates.
[[maybe_unused]] void check_refuses_far_vertex(const tri::CountingDraw& write_counts, double far_x,
                                               const std::string& library,
                                               const std::string& limit) {
  const std::vector<tri::SceneTriangle> far{{{{{0, 0}, {far_x, 0}, {0, 5}}}, tri::colors::white}};
  CHECK_THROWS_WITH(write_counts(8, 8, far),
                    Catch::Contains(library + " cannot draw this scene") && Catch::Contains(limit));
}

[[maybe_unused]] void check_refuses_far_vertex(const tri::CoveragePeer& peer, double far_x,
                                               const std::string& library,
                                               const std::string& limit) {
  tri::Scene scene = tri::peers_test::small_scene(tri::SceneRecipe::Kind::random, 8, 63);
  scene.primitives.push_back(tri::SceneTriangle{{{{0, 0}, {far_x, 0}, {0, 5}}}});
  CHECK_THROWS_WITH(tri::peers_test::measure_coverage_peer(peer, scene),
                    Catch::Contains(library + " cannot draw this scene") && Catch::Contains(limit));
}

}  // namespace

TEST_CASE("Each peer library refuses a scene beyond its fixed-point range, naming the limit",
          "[peers][external_peers]") {
#if TUTORIAL_WITH_PIXMAN
  check_refuses_far_vertex(tri::pixman_write_counts, 40000, "pixman", "32767");  // 16.16
#endif
#if TUTORIAL_WITH_CAIRO
  check_refuses_far_vertex(tri::cairo_write_counts, 1e7, "cairo", "8000000");  // 24.8
#endif
#if TUTORIAL_WITH_AGG
  check_refuses_far_vertex(tri::agg_coverage_peer(), 1e7, "AGG", "4194304");  // 24.8 in an int
#endif
#if TUTORIAL_WITH_FREETYPE
  check_refuses_far_vertex(tri::freetype_coverage_peer(), 40000, "FreeType", "32767");  // short x
#endif
}
