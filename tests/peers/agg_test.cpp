// AGG's anti-aliasing rasterizer as a peer: the exact area, to 8 bits.
#include <catch2/catch.hpp>

#include <cmath>

#include "measure/peers/library_peers.hpp"
#include "tests/peers/peer_test_support.hpp"

using namespace tri::peers_test;
using Kind = tri::SceneRecipe::Kind;

TEST_CASE("AGG's coverage is the exact area to within 3/255, on every pixel of 300 triangles",
          "[peers][agg]") {
  // AGG sums areas exactly in 1/256-pixel units, then cuts the area to 8 bits (a shift, so
  // rounding down), reads 0..255 as 0..1 and blends the result into the image: together
  // within 3/255, more than one 8-bit step (measured: up to about 2.6/255).
  check_eight_bit_area(tri::agg_coverage_peer(), {0, 8}, 61, 3.0 / 255);
}

TEST_CASE("AGG composites triangles over each other: seams on a mesh", "[peers][agg]") {
  const auto r =
      measure_coverage_peer(tri::agg_coverage_peer(), small_scene(Kind::jittered_grid, 8, 62));
  CHECK(r.error.max <= 3.0 / 255);    // each triangle alone is still right
  CHECK(r.error.composed_max > 0.2);  // but drawn one over the other, shared edges show
}

TEST_CASE(
    "AGG's seam on a fan exceeds the 1/e that compositing alone loses: each thin coverage is "
    "cut to 8 bits first",
    "[peers][agg]") {
  // Exact coverages composited over lose at most 1/e of a pixel they tile (chapter 09, step 5):
  // on a mesh, whose pixels hold a few large parts, AGG stays within that and its 8-bit steps.
  const double bound = std::exp(-1.0);
  const auto mesh =
      measure_coverage_peer(tri::agg_coverage_peer(), small_scene(Kind::jittered_grid, 8, 62));
  CHECK(mesh.error.composed_max <= bound + 3.0 / 255);
  // At a fan's centre 300 triangles each cover about 1/300 of the pixel: AGG cuts every part to
  // 8 bits (rounding down) and blends it in 8 bits, so the centre keeps much less than 1 - 1/e.
  const auto fan = measure_coverage_peer(tri::agg_coverage_peer(), small_scene(Kind::fan, 8, 64));
  CHECK(fan.error.max <= 3.0 / 255);  // each triangle alone is still right
  CHECK(fan.error.composed_max > bound + 0.1);
}
