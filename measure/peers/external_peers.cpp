#include "measure/peers/external_peers.hpp"

#if TUTORIAL_WITH_OSMESA
#include "measure/peers/llvmpipe_peer.hpp"
#endif
#include "measure/peers/library_peers.hpp"
#include "measure/peers/peer_builds.hpp"

namespace tri {

std::vector<ExternalPeer> external_peers() {
  std::vector<ExternalPeer> peers;
#if TUTORIAL_WITH_OSMESA
  for (ExternalPeer& peer : llvmpipe_peers()) peers.push_back(std::move(peer));
#endif
#if TUTORIAL_WITH_PIXMAN
  peers.push_back(pixman_peer());
#endif
#if TUTORIAL_WITH_CAIRO
  peers.push_back(cairo_peer());
#endif
  return peers;
}

std::string external_peer_status(std::span<const ExternalPeer> measured) {
  return status_line({{"Mesa llvmpipe", llvmpipe_not_built, "Mesa llvmpipe"},
                      {"pixman", pixman_not_built, "pixman"},
                      {"cairo", cairo_not_built, "cairo"}},
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
  return versions.empty() ? "none" : versions;
}

}  // namespace tri
