#include "measure/peers/external_peers.hpp"

#if TUTORIAL_WITH_OSMESA
#include "measure/peers/llvmpipe_peer.hpp"
#endif
#include "measure/peers/library_peers.hpp"
#include "measure/peers/peer_builds.hpp"

namespace tri {

// Each list builds only its own peers, one block per library found.
std::vector<ExternalPeer> external_peers() {
  std::vector<ExternalPeer> peers;
#if TUTORIAL_WITH_OSMESA
  peers = llvmpipe_peers();
#endif
#if TUTORIAL_WITH_PIXMAN
  peers.push_back(pixman_peer());
#endif
#if TUTORIAL_WITH_CAIRO
  peers.push_back(cairo_peer());
#endif
  return peers;
}

// The report's order: AGG, cairo, pixman, FreeType.
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
#if TUTORIAL_WITH_FREETYPE
  peers.push_back(freetype_coverage_peer());
#endif
  return peers;
}

std::string external_peer_status(std::span<const ExternalPeer> measured) {
  return status_line({{"Mesa llvmpipe", llvmpipe_not_built, "Mesa llvmpipe"},
                      {"pixman", pixman_not_built, "pixman"},
                      {"cairo", cairo_not_built, "cairo"}},
                     measured);
}

std::string coverage_peer_status(std::span<const CoveragePeer> measured) {
  return status_line({{"agg_scanline_aa", agg_not_built, "AGG"},
                      {"cairo_antialias", cairo_not_built, "cairo"},
                      {"pixman_a8", pixman_not_built, "pixman"},
                      {"freetype_smooth", freetype_not_built, "FreeType"}},
                     measured);
}

std::string peer_versions() {
  std::string versions;
  [[maybe_unused]] const auto add = [&versions](const std::string& version) {  // no peer: unused
    versions += (versions.empty() ? "" : ", ") + version;
  };
#if TUTORIAL_WITH_OSMESA
  add(mesa_version());
#endif
#if TUTORIAL_WITH_PIXMAN
  add(pixman_version());
#endif
#if TUTORIAL_WITH_CAIRO
  add(cairo_version());
#endif
#if TUTORIAL_WITH_FREETYPE
  add(freetype_version());
#endif
  return versions.empty() ? "none" : versions;
}

}  // namespace tri
