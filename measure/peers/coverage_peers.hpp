/// @file
/// The anti-aliasing peers this build can measure beside chapter 09's coverage algorithms.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "measure/peers/peer.hpp"

namespace tri {

/// Every anti-aliasing peer this build has (empty when none of their libraries was found).
std::vector<CoveragePeer> coverage_peers();

/// One line for the report: which anti-aliasing peers were measured, or why not.
std::string coverage_peer_status(std::span<const CoveragePeer> measured);

}  // namespace tri
