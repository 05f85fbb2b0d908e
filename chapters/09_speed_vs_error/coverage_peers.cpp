#include "chapters/09_speed_vs_error/coverage_peers.hpp"

#include "chapters/09_speed_vs_error/coverage_peer_libraries.hpp"
#include "chapters/09_speed_vs_error/peer_builds.hpp"

namespace tri::ch09 {

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

namespace {

std::string status(const std::string& peer, const char* not_built,
                   std::span<const CoveragePeer> measured) {
  if (not_built != nullptr) return peer + ": not built (" + not_built + ")";
  for (const CoveragePeer& p : measured) {
    if (p.name == peer) return peer + ": measured";
  }
  return peer + ": built, not selected by --only";
}

}  // namespace

std::string coverage_peer_status(std::span<const CoveragePeer> measured) {
  return status("agg_scanline_aa", agg_not_built, measured) + "; " +
         status("cairo_antialias", cairo_not_built, measured) + "; " +
         status("pixman_a8", pixman_not_built, measured);
}

}  // namespace tri::ch09
