#include <sstream>

#include <catch2/catch.hpp>

#include "chapters/10_speed_vs_error/external_peers.hpp"
#include "measure/machine.hpp"

TEST_CASE("The CPU model is the first model name line of /proc/cpuinfo",
          "[10_speed_vs_error][machine]") {
  std::istringstream cpuinfo(
      "processor\t: 0\nvendor_id\t: AuthenticAMD\nmodel\t\t: 1\n"
      "model name\t: AMD EPYC 7B13 64-Core Processor  \nprocessor\t: 1\n"
      "model name\t: something else\n");
  CHECK(tri::cpu_model_from(cpuinfo) == "AMD EPYC 7B13 64-Core Processor");
}

TEST_CASE("Without a model name line the CPU model is unknown", "[10_speed_vs_error][machine]") {
  std::istringstream arm("processor\t: 0\nBogoMIPS\t: 50.00\nmodel name\t:   \n");
  CHECK(tri::cpu_model_from(arm) == "unknown");
  std::istringstream empty("");
  CHECK(tri::cpu_model_from(empty) == "unknown");
}

TEST_CASE("The machine description names the compiler, the build type and the external peers",
          "[10_speed_vs_error][machine]") {
  const auto peers = tri::ch10::external_peers();
  const tri::Machine machine = tri::describe_machine(tri::ch10::external_peer_status(peers));
  CHECK_FALSE(machine.cpu_model.empty());
  CHECK_FALSE(machine.compiler.empty());
  CHECK_FALSE(machine.build_type.empty());
  CHECK(machine.external_peers == tri::ch10::external_peer_status(peers));
}
