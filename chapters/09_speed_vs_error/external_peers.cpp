#include "chapters/09_speed_vs_error/external_peers.hpp"

#if TUTORIAL_WITH_OSMESA
#include "chapters/09_speed_vs_error/llvmpipe_peer.hpp"
#endif
#if TUTORIAL_WITH_PIXMAN
#include "chapters/09_speed_vs_error/pixman_peer.hpp"
#endif
#if TUTORIAL_WITH_CAIRO
#include "chapters/09_speed_vs_error/cairo_peer.hpp"
#endif

#include "chapters/09_speed_vs_error/peer_builds.hpp"

namespace tri::ch09 {

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

namespace {

// "pixman: measured (pixman_a1)", "… built, not selected by --only" or "… not built (reason)".
std::string library_status(const std::string& library, const char* not_built,
                           const std::string& name_prefix, std::span<const ExternalPeer> measured) {
  if (not_built != nullptr) return library + ": not built (" + not_built + ")";
  std::string names;
  for (const ExternalPeer& peer : measured) {
    if (peer.name.starts_with(name_prefix)) names += (names.empty() ? "" : ", ") + peer.name;
  }
  return library +
         (names.empty() ? ": built, not selected by --only" : ": measured (" + names + ")");
}

}  // namespace

std::string external_peer_status(std::span<const ExternalPeer> measured) {
  return library_status("Mesa llvmpipe", llvmpipe_not_built, "mesa_llvmpipe", measured) + "; " +
         library_status("pixman", pixman_not_built, "pixman", measured) + "; " +
         library_status("cairo", cairo_not_built, "cairo", measured);
}

}  // namespace tri::ch09
