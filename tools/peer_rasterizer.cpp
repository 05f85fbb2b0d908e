// An external peer behind the conformance suite's --command protocol: reads a scene file, draws its
// triangles with the named peer (Mesa's llvmpipe, pixman, cairo) and writes the write counts as a
// binary PGM, top row first, as raster --counts does. A scene the peer cannot draw (beyond its
// fixed-point range) or cannot read (NaN) is refused with a message and exit status 1.
#include <iostream>
#include <string>
#include <vector>

#include "common/cli.hpp"
#include "common/image_io.hpp"
#include "common/scene.hpp"
#include "measure/drawable.hpp"
#include "measure/peers/external_peers.hpp"
#include "measure/render_scene.hpp"

int main(int argc, char** argv) {
  // The help and the refusal list the peers this build has, from the list itself.
  const auto peers = tri::external_peers();
  std::vector<std::string> names;
  for (const auto& p : peers) names.emplace_back(p.name);
  const std::string valid = names.empty() ? "none" : tri::comma_separated(names);
  const tri::CommandLine command_line(
      "peer_rasterizer",
      "Draws a scene with one external peer and writes its write counts, so that the\n"
      "conformance suite can grade it through --command:\n"
      "  conformance --command 'peer_rasterizer --peer NAME --scene {scene} --counts {counts}'",
      {{"peer", "NAME", "the peer, one this build has: " + valid},
       {"scene", "FILE", "the scene to draw (docs/DESIGN.md section 4)"},
       {"counts", "FILE.pgm", "where the write counts go"}});
  return tri::run_command_line(
      command_line, argc, argv, std::cout, std::cerr, [&](const tri::CliArguments& args) {
        const std::string name = args.value_or("peer", "");
        const tri::ExternalPeer* peer = tri::find_named(peers, name);
        if (peer == nullptr) {
          throw tri::UsageError("--peer: unknown peer '" + name + "' (this build has: " + valid +
                                ")");
        }
        const auto scene_path = args.value("scene");
        const auto counts_path = args.value("counts");
        if (!scene_path || !counts_path) throw tri::UsageError("--scene and --counts are required");
        const tri::Scene scene = tri::load_scene(*scene_path);
        const tri::WriteCounts counts =
            peer->write_counts(scene.width, scene.height, tri::scene_triangles(scene));
        tri::write_file_atomically(
            *counts_path, tri::encode_counts_pgm(scene.width, scene.height, counts.counts));
        return tri::exit_success;
      });
}
