#include "external_peers.hpp"

#if TUTORIAL_WITH_OSMESA
#include "llvmpipe_peer.hpp"
#endif
#if TUTORIAL_WITH_PIXMAN
#include "pixman_peer.hpp"
#endif
#if TUTORIAL_WITH_CAIRO
#include "cairo_peer.hpp"
#endif

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

// "llvmpipe: measured (mesa_llvmpipe_1_thread, …)", "… not selected by --only" or "… not built
// (reason)" for one library.
std::string library_status(const std::string& library, bool built, const std::string& why_not,
                           const std::string& name_prefix, std::span<const ExternalPeer> measured) {
  if (!built) return library + ": not built (" + why_not + ")";
  std::string names;
  for (const ExternalPeer& peer : measured) {
    if (peer.name.starts_with(name_prefix)) names += (names.empty() ? "" : ", ") + peer.name;
  }
  return library +
         (names.empty() ? ": built, not selected by --only" : ": measured (" + names + ")");
}

}  // namespace

std::string external_peer_status(std::span<const ExternalPeer> measured) {
#if TUTORIAL_WITH_OSMESA
  const bool llvmpipe = true;
  const std::string llvmpipe_why_not;
#else
  const bool llvmpipe = false;
  const std::string llvmpipe_why_not = TUTORIAL_LLVMPIPE_SKIPPED_BECAUSE;
#endif
#if TUTORIAL_WITH_PIXMAN
  const bool pixman = true;
  const std::string pixman_why_not;
#else
  const bool pixman = false;
  const std::string pixman_why_not = TUTORIAL_PIXMAN_SKIPPED_BECAUSE;
#endif
#if TUTORIAL_WITH_CAIRO
  const bool cairo = true;
  const std::string cairo_why_not;
#else
  const bool cairo = false;
  const std::string cairo_why_not = TUTORIAL_CAIRO_SKIPPED_BECAUSE;
#endif
  return library_status("Mesa llvmpipe", llvmpipe, llvmpipe_why_not, "mesa_llvmpipe", measured) +
         "; " + library_status("pixman", pixman, pixman_why_not, "pixman", measured) + "; " +
         library_status("cairo", cairo, cairo_why_not, "cairo", measured);
}

}  // namespace tri::ch09
