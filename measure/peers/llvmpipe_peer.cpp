#include "measure/peers/llvmpipe_peer.hpp"

#include <cstdlib>
#include <optional>
#include <string>

#include "measure/child_process.hpp"
#include "measure/peers/llvmpipe_canvas.hpp"

namespace tri {

Timing time_llvmpipe_here(const PreparedScene& prepared, const TimingPlan& plan) {
  // As for the book's algorithms: the buffer and the triangles are ready before the clock.
  LlvmpipeCanvas canvas(prepared.scene.width, prepared.scene.height, LlvmpipeCanvas::Pixels::rgba8);
  canvas.upload(prepared.triangles);
  return time_runs([&canvas] { canvas.draw(); }, plan);
}

PeerResult measure_llvmpipe_here(const PreparedScene& prepared, const TimingPlan& plan) {
  const int width = prepared.scene.width, height = prepared.scene.height;
  const Timing timing = time_llvmpipe_here(prepared, plan);
  // One context for the scene and all six vertex orders of the error scene: it has the scene's
  // size, and measure_error refuses counts of any other size.
  LlvmpipeCanvas counter(width, height, LlvmpipeCanvas::Pixels::write_counts);
  return peer_result(
      timing,
      [&counter](int, int, std::span<const SceneTriangle> triangles) {
        return counter.write_counts(triangles);
      },
      prepared);
}

namespace {

// LP_NUM_THREADS set to threads, or removed for nothing.
void set_llvmpipe_threads(const std::optional<std::string>& threads) {
  if (threads) {
    ::setenv("LP_NUM_THREADS", threads->c_str(), 1);
  } else {
    ::unsetenv("LP_NUM_THREADS");
  }
}

// A peer whose measurement runs in a child with LP_NUM_THREADS set (or removed, for nothing).
ExternalPeer llvmpipe_peer(std::string_view name, std::string_view summary, bool threaded,
                           std::optional<std::string> threads) {
  return {aliased_peer_description(name, summary, CoverageRule::bottom_left, threaded),
          "Mesa llvmpipe",
          [threads](const PreparedScene& prepared, const TimingPlan& plan) {
            return run_in_child<PeerResult>([&] {
              set_llvmpipe_threads(threads);
              return measure_llvmpipe_here(prepared, plan);
            });
          },
          // Called in a child process already (ExternalPeer::time), so Mesa starts there.
          [threads](const PreparedScene& prepared, const TimingPlan& plan) {
            set_llvmpipe_threads(threads);
            return time_llvmpipe_here(prepared, plan);
          },
          // Called by the peer's own adapter process, where Mesa may start.
          [threads](int width, int height, std::span<const SceneTriangle> triangles) {
            set_llvmpipe_threads(threads);
            return llvmpipe_write_counts(width, height, triangles);
          }};
}

}  // namespace

std::vector<ExternalPeer> llvmpipe_peers() {
  return {
      llvmpipe_peer("mesa_llvmpipe_1_thread",
                    "Mesa's llvmpipe through OSMesa, all work on the calling thread", false, "0"),
      llvmpipe_peer("mesa_llvmpipe_default",
                    "Mesa's llvmpipe through OSMesa, one rasterizer thread per core", true,
                    std::nullopt)};
}

std::string mesa_version() {
  const std::string version = run_in_child_process(
      [] { return LlvmpipeCanvas(1, 1, LlvmpipeCanvas::Pixels::rgba8).version(); });
  const auto mesa = version.find("Mesa ");
  return mesa == std::string::npos ? "Mesa (" + version + ")" : version.substr(mesa);
}

}  // namespace tri
