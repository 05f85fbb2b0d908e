#include <map>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "chapters/10_speed_vs_error/summary.hpp"
#include "measure/registry.hpp"

using tri::ch10::AlgorithmSummary;
using tri::ch10::Measurement;

namespace {

// A measurement with round numbers: `pixels` written in `seconds`, and an error report.
Measurement made_up(std::string algorithm, std::string scene, bool mesh, double seconds,
                    std::uint64_t pixels, std::uint64_t covered, std::uint64_t missed,
                    std::uint64_t extra, std::uint64_t gaps) {
  Measurement m;
  m.algorithm = std::move(algorithm);
  m.chapter = "07_exact_coverage";
  m.rule = "approximate";
  m.scene = std::move(scene);
  m.grid = "integer";
  m.mesh = mesh;
  m.triangles = 1000;
  m.written_pixels = pixels;
  m.timing.seconds = {seconds, seconds, seconds};
  m.fill_ceiling_mpix_per_s = 1000;
  m.error.covered = covered;
  m.error.missed = missed;
  m.error.extra = extra;
  m.error.gaps = gaps;
  m.error.overdraw = gaps;
  return m;
}

}  // namespace

TEST_CASE("A summary takes geometric means of speeds and sums of errors",
          "[10_speed_vs_error][step5][summary]") {
  const std::vector<Measurement> rows{
      made_up("a", "tiny", false, 0.001, 1'000'000, 100, 1, 2, 5),  // 1000 Mpix/s
      made_up("b", "tiny", false, 0.002, 1'000'000, 100, 0, 0, 0),
      made_up("a", "large", false, 0.1, 1'000'000, 1000, 3, 4, 6),  // 10 Mpix/s
      made_up("a", "mesh", true, 0.01, 1'000'000, 900, 0, 0, 7),    // 100 Mpix/s
  };
  const std::vector<AlgorithmSummary> summaries = tri::ch10::summarize(rows);
  REQUIRE(summaries.size() == 2);
  const AlgorithmSummary& a = summaries[0];
  CHECK(a.algorithm == "a");
  CHECK(a.scenes == 3);
  CHECK(a.large_mpix_per_s == Approx(10));
  CHECK(a.tiny_tris_per_s == Approx(1e6));
  CHECK(a.mesh_tris_per_s == Approx(1e5));
  CHECK(a.mpix_per_s == Approx(100));  // (1000 * 10 * 100)^(1/3)
  CHECK(a.ratio_to_ceiling == Approx(0.1));
  CHECK(a.covered == 2000);
  CHECK(a.missed == 4);
  CHECK(a.extra == 6);
  CHECK(a.error_rate() == Approx(10.0 / 2000));
  CHECK(a.gaps == 7);  // from the mesh scene only
  CHECK(a.overdraw == 7);
  const AlgorithmSummary& b = summaries[1];
  CHECK(b.algorithm == "b");
  CHECK(b.error_rate() == 0);
  CHECK(b.large_mpix_per_s == 0);  // no large scene measured
}

TEST_CASE("The registry names the precision families and their bits",
          "[10_speed_vs_error][step5][summary]") {
  std::map<std::string, std::vector<int>> families;
  for (const tri::TriangleAlgorithm& a : tri::registered_algorithms()) {
    if (!a.precision_family.empty()) {
      families[std::string(a.chapter) + " " + std::string(a.precision_family)].push_back(
          a.precision_bits);
    }
  }
  CHECK(families == std::map<std::string, std::vector<int>>{
                        {"06_barycentric barycentric", {24, 53}},
                        {"07_exact_coverage fixed_point", {8, 4, 2, 0}},
                    });
}

TEST_CASE("Precision families join members of one chapter from fewer to more bits",
          "[10_speed_vs_error][step5][summary]") {
  const auto summary = [](const char* chapter, const char* family, int bits) {
    AlgorithmSummary s;
    s.chapter = chapter;
    s.precision_family = family;
    s.precision_bits = bits;
    return s;
  };
  const std::vector<AlgorithmSummary> summaries{
      summary("07", "fixed_point", 8),
      summary("07", "fixed_point", 0),
      summary("05", "", 0),
      summary("07", "fixed_point", 4),
      summary("06", "barycentric", 53),
      summary("06", "barycentric", 24),
      summary("08", "lonely", 16),
      summary("08", "fixed_point", 2),
  };
  const auto families = tri::ch10::precision_families(summaries);
  REQUIRE(families.size() == 2);
  CHECK(families[0] == std::vector<std::size_t>{1, 3, 0});
  CHECK(families[1] == std::vector<std::size_t>{5, 4});
}
