#include "external_peers.hpp"

#include <catch2/catch.hpp>
#include <set>
#include <string>

#include "registry.hpp"

TEST_CASE("External peers have their own names, filed under 'external'", "[external_peers]") {
  const auto peers = tri::ch09::external_peers();
  const auto algorithms = tri::registered_algorithms();
  std::set<std::string> names;
  for (const tri::ch09::ExternalPeer& peer : peers) {
    CAPTURE(peer.name);
    CHECK(names.insert(peer.name).second);
    CHECK(tri::find_algorithm(algorithms, peer.name) == nullptr);  // --only can tell them apart
    CHECK(peer.chapter == "external");
    CHECK(static_cast<bool>(peer.measure));
  }
}

TEST_CASE("The Machine line says which peers were measured, or why none was", "[external_peers]") {
  const auto peers = tri::ch09::external_peers();
  const std::string all = tri::ch09::external_peer_status(peers);
  const std::string none = tri::ch09::external_peer_status({});
  if (peers.empty()) {
    CHECK((all == "not built (libosmesa6-dev not found)" ||
           all == "not built (TUTORIAL_LLVMPIPE_PEER=OFF)"));
    CHECK(none == all);
  } else {
    REQUIRE(peers.size() == 2);
    CHECK(peers[0].name == "mesa_llvmpipe_1_thread");
    CHECK_FALSE(peers[0].threaded);
    CHECK(peers[1].name == "mesa_llvmpipe_default");
    CHECK(peers[1].threaded);
    CHECK(
        all.starts_with("measured: mesa_llvmpipe_1_thread, mesa_llvmpipe_default (Mesa's "
                        "llvmpipe through "));
    CHECK(none == "built with OSMesa, not selected by --only");
  }
}
