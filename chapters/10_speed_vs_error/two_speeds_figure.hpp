/// @file
/// Step 3's figure: the two speeds of a few algorithms beside the write ceiling, drawn from a
/// committed measurement snapshot, so it changes only when the snapshot is refreshed.
#pragma once

#include <string>
#include <vector>

#include "common/figures.hpp"
#include "measure/snapshot_reading.hpp"

namespace tri::ch10 {

/// What the figure draws, read from a snapshot.
struct TwoSpeeds {
  struct Row {
    std::string algorithm;
    double large_mpix_per_s = 0;  ///< geometric mean over the two large scenes
    double tiny_tris_per_s = 0;   ///< geometric mean over the two tiny scenes
  };
  std::vector<Row> rows;  ///< the figure's algorithms that the snapshot has, in the figure's order
  /// The write ceiling of the large scenes: each scene's Mpix/s divided by its ratio to the
  /// ceiling (taken from the first row), then the geometric mean over the two grids, as the rows'.
  double ceiling_mpix_per_s = 0;
};

/// The algorithms the figure compares, one or two per chapter and the pixman peer: the scanline
/// and the edge function (chapters 04, 05), chapter 06's barycentric weights in double, chapter
/// 08's hybrid and batched setup.
std::vector<std::string> two_speeds_algorithms();

/// The figure's numbers from a snapshot; throws std::runtime_error when it holds none of the
/// algorithms or no ratio to the ceiling for the large scenes.
TwoSpeeds two_speeds_of(const Snapshot& snapshot);

/// The figure: Mpixels/s on large triangles as bars beside the write ceiling, triangles/s on tiny
/// triangles beside them, the machine, compiler, date and commit from the snapshot's header.
SvgFigure two_speeds_figure(const Snapshot& snapshot);

}  // namespace tri::ch10
