#include "external_peers.hpp"

#if TUTORIAL_WITH_OSMESA
#include "llvmpipe_peer.hpp"
#endif

namespace tri::ch09 {

std::vector<ExternalPeer> external_peers() {
#if TUTORIAL_WITH_OSMESA
  return llvmpipe_peers();
#else
  return {};
#endif
}

std::string external_peer_status(std::span<const ExternalPeer> measured) {
#if TUTORIAL_WITH_OSMESA
  if (measured.empty()) return "built with OSMesa, not selected by --only";
  std::string names;
  for (const ExternalPeer& peer : measured) names += (names.empty() ? "" : ", ") + peer.name;
  return "measured: " + names + " (Mesa's llvmpipe through " TUTORIAL_OSMESA_LIBRARY ")";
#else
  (void)measured;
  return "not built (" TUTORIAL_LLVMPIPE_SKIPPED_BECAUSE ")";
#endif
}

}  // namespace tri::ch09
