// cairo, filling aliased triangle paths, as a peer: its pixels against the oracle, its limits.
#include <catch2/catch.hpp>

#include <algorithm>
#include <numeric>
#include <string>

#include "measure/peers/library_peers.hpp"
#include "tests/peers/peer_test_support.hpp"

using namespace tri::peers_test;
using Kind = tri::SceneRecipe::Kind;

TEST_CASE(
    "cairo differs from the oracle at centres on no edge: the report's 1/256-grid slivers, mesh "
    "and fan",
    "[peers][cairo]") {
  // Not a tie rule: on these scenes cairo misses or adds pixels whose centres lie within a
  // hundredth of a pixel of an edge but exactly on none (nearest_edge_distance is 0 only there).
  for (const std::string name : {"slivers", "mesh", "fan"}) {
    const auto prepared = quick_scene(name, "1/256");
    const Differences d = differences_from_oracle(tri::cairo_write_counts, prepared.scene.width,
                                                  prepared.scene.height, prepared.triangles);
    CAPTURE(name, d.missed, d.extra);
    CHECK(d.missed + d.extra > 0);
    for (const double distance : d.edge_distances) {
      CAPTURE(distance);
      CHECK(distance > 0);
      CHECK(distance < 0.01);
    }
  }
}

TEST_CASE("cairo follows no exact tie rule: an integer-grid mesh gets centres twice or never",
          "[peers][cairo]") {
  const auto triangles = tri::scene_triangles(small_scene(Kind::jittered_grid, 0, 11));
  const auto counts = tri::cairo_write_counts(64, 48, triangles).counts;
  const auto oracle = oracle_counts(64, 48, triangles).counts;
  std::size_t twice = 0, never = 0;
  for (std::size_t i = 0; i < counts.size(); ++i) {
    twice += counts[i] >= 2 && oracle[i] == 1;
    never += counts[i] == 0 && oracle[i] == 1;
  }
  CHECK(twice + never > 0);
  CHECK(differing_pixels(counts, oracle) == twice + never);
}

TEST_CASE("cairo's row in the report: timed, with its error measured", "[peers][cairo]") {
  const auto settings = tri::ch10::bench_settings(tri::ch10::SuiteSize::tiny);
  const tri::ExternalPeer peer = tri::cairo_peer();
  CHECK(peer.name == "cairo_no_antialias");
  CHECK(peer.rule == tri::CoverageRule::approximate);
  const auto prepared = tri::prepare_scene(settings.scenes.front(), 0);
  const tri::PeerResult result = peer.measure(prepared, settings.timing);
  CHECK(result.timing.seconds.median > 0);
  CHECK(result.written_pixels > 0);
  CHECK(result.error.covered > 0);
}

TEST_CASE(
    "cairo's anti-aliasing is the area in x over 15 sample rows: within 1/15 of the exact area",
    "[peers][cairo][coverage]") {
  const auto r = on_random_triangles(tri::cairo_coverage_peer(), 8, 81);
  CHECK(r.error.max <= 1.0 / 15 + 1.0 / 255);
  CHECK(r.error.max > 2.0 / 255);  // rows are sampled, so not the exact area
  CHECK(r.error.mean > 0);
}

TEST_CASE("cairo adds the coverage of an A8 mesh with the ADD operator: no seams",
          "[peers][cairo][coverage]") {
  const auto r =
      measure_coverage_peer(tri::cairo_coverage_peer(), small_scene(Kind::jittered_grid, 8, 62));
  // Each triangle's own error, at most its sample rows' and 8 bits', adds up at a shared edge,
  // but no pixel loses what compositing over loses (AGG on the same mesh: more than 0.2).
  INFO("each alone " << r.error.max << ", the mesh " << r.error.composed_max);
  CHECK(r.error.composed_max <= 2 * r.error.max);
  CHECK(r.error.composed_max < 0.1);
}
