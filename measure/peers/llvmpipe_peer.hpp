/// @file
/// Mesa's llvmpipe as the report's external peer, in its two configurations: everything on the
/// calling thread, and Mesa's default of one rasterizer thread per core. Built only with OSMesa.
#pragma once

#include <string>
#include <vector>

#include "measure/peers/peer.hpp"

namespace tri {

/// Times llvmpipe drawing the prepared scene in this process (with whatever LP_NUM_THREADS says).
Timing time_llvmpipe_here(const PreparedScene& prepared, const TimingPlan& plan);

/// Times llvmpipe on the prepared scene in this process (with whatever LP_NUM_THREADS says)
/// and measures its write counts and its error against the oracle.
PeerResult measure_llvmpipe_here(const PreparedScene& prepared, const TimingPlan& plan);

/// "mesa_llvmpipe_1_thread" (LP_NUM_THREADS=0: no rasterizer threads, all work on the calling
/// thread) and "mesa_llvmpipe_default" (LP_NUM_THREADS unset). llvmpipe reads the variable once
/// per process, so each measurement runs in a child process of its own, and this process must
/// never start Mesa itself (a child forked from a process with llvmpipe's threads can hang).
/// Their rule is "bottom-left": the oracle's top-left rule upside down, as the tests show.
std::vector<ExternalPeer> llvmpipe_peers();

/// "Mesa 22.3.6": the Mesa release behind llvmpipe, asked in a child process (see above).
std::string mesa_version();

}  // namespace tri
