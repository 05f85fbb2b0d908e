/// @file
/// A measurement snapshot: the numbers of one run that the book quotes, as KEY,VALUE lines under
/// a header naming the machine, compiler, commit and date (read by tools/listings/measured.hpp).
#pragma once

#include <span>
#include <string>

#include "chapters/10_speed_vs_error/report.hpp"

namespace tri::ch10 {

/// What the header says beyond what the report knows: the commit measured, the UTC date, the
/// peer libraries' releases (external_peers.hpp's peer_versions) and a note on the run (for
/// example that the machine was shared).
struct SnapshotHeader {
  std::string commit;
  std::string date;
  std::string peers;
  std::string note;
};

/// The snapshot text. Header lines `# NAME: TEXT` (machine, compiler, commit, date, peers, note),
/// then keys: `<algorithm>.<metric>` for the summaries, in the report's order (chapter, a text
/// such as `03` or `external`; threaded, 1 or 0; mpix_per_s,
/// large_mpix_per_s, tiny_tris_per_s, mesh_tris_per_s, ratio_to_ceiling, error_rate; the coverage
/// algorithms' cost_vs_fastest, tris_per_s, mean_error, max_error) and
/// `<algorithm>.<scene>_<grid>.<metric>` per scene (median_s, tris_per_s, mpix_per_s,
/// ratio_to_ceiling), the grid `1/256` written `1_256`; then, with Blend2D's shapes,
/// `blend2d_shapes.vectors` (host_instruction_set) and `<drawer>.blend2d_<N>.calls_per_ms` per
/// drawer and size.
std::string snapshot_text(const BenchReport& report, const CoverageReport& coverage,
                          const SnapshotHeader& header, std::span<const ShapeRate> shapes = {});

/// Today's date in UTC, as YYYY-MM-DD.
std::string utc_date();

}  // namespace tri::ch10
