// AGG's anti-aliasing rasterizer as a peer: the exact area, to 8 bits.
#include <catch2/catch.hpp>

#include "chapters/10_speed_vs_error/library_peers.hpp"
#include "chapters/10_speed_vs_error/peer_test_support.hpp"

using namespace tri::ch10::test;
using Kind = tri::SceneRecipe::Kind;

TEST_CASE("AGG's coverage is the exact area to within 3/255, on every pixel of 300 triangles",
          "[10_speed_vs_error][agg]") {
  for (const int grid_bits : {0, 8}) {
    INFO("grid 1/2^" << grid_bits);
    const auto r = measure_coverage_peer(tri::ch10::agg_coverage_peer(),
                                         small_scene(Kind::random, grid_bits, 61));
    CHECK(r.error.triangles == 300);
    CHECK(r.error.pixels > 1000);
    // AGG sums areas exactly in 1/256-pixel units, then cuts the area to 8 bits (a shift, so
    // rounding down), reads 0..255 as 0..1 and blends the result into the image: together
    // within 3/255, more than one 8-bit step (measured: up to about 2.6/255).
    CHECK(r.error.max <= 3.0 / 255);
    CHECK(r.error.max > 1.0 / 255);
    CHECK(r.error.mean > 0);
    CHECK(r.touched_pixels > 0);
  }
}

TEST_CASE("AGG composites triangles over each other: seams on a mesh", "[10_speed_vs_error][agg]") {
  const auto r = measure_coverage_peer(tri::ch10::agg_coverage_peer(),
                                       small_scene(Kind::jittered_grid, 8, 62));
  CHECK(r.error.max <= 3.0 / 255);    // each triangle alone is still right
  CHECK(r.error.composed_max > 0.2);  // but drawn one over the other, shared edges show
}

TEST_CASE("AGG refuses a scene beyond its 24.8 fixed-point range, naming the limit",
          "[10_speed_vs_error][agg]") {
  tri::Scene scene = small_scene(Kind::random, 8, 63);
  scene.primitives.push_back(tri::SceneTriangle{{{{0, 0}, {1e7, 0}, {0, 5}}}});
  CHECK_THROWS_WITH(measure_coverage_peer(tri::ch10::agg_coverage_peer(), scene),
                    Catch::Contains("AGG cannot draw this scene"));
}
