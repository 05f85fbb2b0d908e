#include "chapters/09_speed_vs_error/coverage_peers.hpp"

namespace tri::ch09 {

std::vector<CoveragePeer> coverage_peers() {
  return {};  // AGG, cairo and pixman come here, each where its library was found
}

std::string coverage_peer_status(std::span<const CoveragePeer> measured) {
  if (measured.empty()) return "none measured";
  std::string names;
  for (const CoveragePeer& peer : measured) names += (names.empty() ? "" : ", ") + peer.name;
  return "measured (" + names + ")";
}

}  // namespace tri::ch09
