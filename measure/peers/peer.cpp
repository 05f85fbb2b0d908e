#include "measure/peers/peer.hpp"

#include <numeric>

namespace tri {

PeerResult peer_result(const Timing& timing, const CountingDraw& draw,
                       const PreparedScene& prepared) {
  PeerResult result;
  result.timing = timing;
  const WriteCounts drawn = draw(prepared.scene.width, prepared.scene.height, prepared.triangles);
  result.written_pixels =
      std::accumulate(drawn.counts.begin(), drawn.counts.end(), std::uint64_t{0});
  result.error = measure_error(draw, prepared.error_scene);
  return result;
}

ExternalPeer in_process_peer(const Drawable& description, std::string_view library,
                             std::function<Timing(const PreparedScene&, const TimingPlan&)> time,
                             CountingDraw draw) {
  return {description, library,
          [time, draw](const PreparedScene& prepared, const TimingPlan& plan) {
            return peer_result(time(prepared, plan), draw, prepared);
          },
          std::move(time), draw};
}

}  // namespace tri
