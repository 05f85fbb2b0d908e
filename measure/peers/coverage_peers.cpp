#include "measure/peers/coverage_peers.hpp"

#include "measure/peers/library_peers.hpp"
#include "measure/peers/peer_builds.hpp"

namespace tri {

std::vector<CoveragePeer> coverage_peers() {
  std::vector<CoveragePeer> peers;
#if TUTORIAL_WITH_AGG
  peers.push_back(agg_coverage_peer());
#endif
#if TUTORIAL_WITH_CAIRO
  peers.push_back(cairo_coverage_peer());
#endif
#if TUTORIAL_WITH_PIXMAN
  peers.push_back(pixman_coverage_peer());
#endif
  return peers;
}

std::string coverage_peer_status(std::span<const CoveragePeer> measured) {
  return status_line({{"agg_scanline_aa", agg_not_built, "AGG"},
                      {"cairo_antialias", cairo_not_built, "cairo"},
                      {"pixman_a8", pixman_not_built, "pixman"}},
                     measured);
}

}  // namespace tri
