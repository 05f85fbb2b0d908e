/// @file
/// The peers this build can measure, each where its library was found: Mesa's llvmpipe, pixman
/// and cairo beside the aliased algorithms; AGG, cairo and pixman beside the anti-aliasing ones.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "measure/peers/peer.hpp"

namespace tri {

/// Every external peer this build has (empty without OSMesa).
std::vector<ExternalPeer> external_peers();

/// Every anti-aliasing peer this build has (empty when none of their libraries was found).
std::vector<CoveragePeer> coverage_peers();

/// One line for the report's Machine table: which peers were measured, or why none was.
/// `measured` are the peers the run actually measured (--only can leave them out).
std::string external_peer_status(std::span<const ExternalPeer> measured);

/// One line for the report: which anti-aliasing peers were measured, or why not.
std::string coverage_peer_status(std::span<const CoveragePeer> measured);

/// The releases of the peer libraries this build measures, e.g. "Mesa 22.3.6, pixman 0.42.2,
/// cairo 1.16.0"; "none" when it has none.
std::string peer_versions();

}  // namespace tri
