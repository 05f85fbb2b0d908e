// FreeType's smooth rasterizer as a peer: the area of its outline, to 8 bits.
#include <catch2/catch.hpp>

#include "measure/peers/library_peers.hpp"
#include "tests/peers/peer_test_support.hpp"

using namespace tri::peers_test;
using Kind = tri::SceneRecipe::Kind;

TEST_CASE("FreeType's coverage is the exact area to within 2/255 on its own 1/64 grid",
          "[peers][freetype]") {
  // The area of the outline, cut to 8 bits (measured: up to about 1.9/255).
  check_eight_bit_area(tri::freetype_coverage_peer(), {0, 6}, 91, 2.0 / 255);
}

TEST_CASE("FreeType rounds 1/256-grid vertices to its 26.6 fixed point: more than 2/255 off",
          "[peers][freetype]") {
  const auto r = on_random_triangles(tri::freetype_coverage_peer(), 8, 91);
  // A vertex moved by up to 1/128 of a pixel moves an edge's area by as much (measured: about
  // 4.4/255 at the worst pixel).
  CHECK(r.error.max > 2.0 / 255);
  CHECK(r.error.max <= 6.0 / 255);
}

TEST_CASE("FreeType's spans add up: a mesh drawn whole keeps its shared edges within 6/255",
          "[peers][freetype]") {
  const auto r =
      measure_coverage_peer(tri::freetype_coverage_peer(), small_scene(Kind::jittered_grid, 8, 92));
  CHECK(r.error.composed_pixels > 0);
  CHECK(r.error.composed_max <= 6.0 / 255);  // added, not composited over: no seam beyond rounding
}
