#include <sstream>

#include <catch2/catch.hpp>

#include "measure/machine.hpp"
#include "measure/peers/external_peers.hpp"

TEST_CASE("The CPU model is the first model name line of /proc/cpuinfo", "[measure][machine]") {
  std::istringstream cpuinfo(
      "processor\t: 0\nvendor_id\t: AuthenticAMD\nmodel\t\t: 1\n"
      "model name\t: AMD EPYC 7B13 64-Core Processor  \nprocessor\t: 1\n"
      "model name\t: something else\n");
  CHECK(tri::cpu_model_from(cpuinfo) == "AMD EPYC 7B13 64-Core Processor");
}

TEST_CASE("Without a model name line the CPU model is unknown", "[measure][machine]") {
  std::istringstream arm("processor\t: 0\nBogoMIPS\t: 50.00\nmodel name\t:   \n");
  CHECK(tri::cpu_model_from(arm) == "unknown");
  std::istringstream empty("");
  CHECK(tri::cpu_model_from(empty) == "unknown");
}

TEST_CASE("The machine description names the compiler, the build type and the external peers",
          "[measure][machine]") {
  const auto peers = tri::external_peers();
  const tri::Machine machine = tri::describe_machine(tri::external_peer_status(peers));
  CHECK_FALSE(machine.cpu_model.empty());
  CHECK_FALSE(machine.compiler.empty());
  CHECK_FALSE(machine.build_type.empty());
  CHECK(machine.external_peers == tri::external_peer_status(peers));
}
