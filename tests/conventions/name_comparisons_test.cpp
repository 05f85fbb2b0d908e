#include "tests/conventions/name_comparisons.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "measure/peers/external_peers.hpp"
#include "measure/registry.hpp"

namespace tri::conventions {
namespace {

namespace fs = std::filesystem;

std::vector<std::string_view> registered_names(const std::vector<Drawable>& drawables) {
  std::vector<std::string_view> names;
  for (const Drawable& d : drawables) names.push_back(d.name);
  return names;
}

std::string read(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST_CASE("A comparison with a registered name is found on either side and in a kept constant",
          "[conventions][drawables]") {
  const std::vector<std::string_view> names{"fast_spans", "exact_oracle"};
  const std::string source =
      "if (a.name == \"fast_spans\") x();\n"
      "if (\"exact_oracle\" != b.name) y();\n"
      "const ok = entry.name === 'fast_spans';\n"
      "constexpr std::string_view chosen = \"fast_spans\";\n"
      "if (a.name.starts_with(\"exact_oracle\")) z();\n";
  const auto found = name_comparisons(source, names);
  REQUIRE(found.size() == 5);
  CHECK(found[0].name == "fast_spans");
  CHECK(found[0].line == 1);
  CHECK(found[1].name == "exact_oracle");
  CHECK(found[1].line == 2);
  CHECK(found[2].line == 3);
  CHECK(found[3].line == 4);
  CHECK(found[4].line == 5);
}

TEST_CASE("A registered name in a message, a list or a registration is not a comparison",
          "[conventions][drawables]") {
  const std::vector<std::string_view> names{"fast_spans"};
  const std::string source =
      "out << \"drawn by fast_spans\";\n"
      "const char* names[] = {\"fast_spans\", \"fast_simd\"};\n"
      "variant(\"fast_spans\", \"summary\", draw);\n"
      "{.name = \"fast_spans\",\n"
      "if (a.name == \"fast_spans_wide\") x();\n";
  CHECK(name_comparisons(source, names).empty());
}

TEST_CASE("The convention skips tests, registrations and builds, and checks the other sources",
          "[conventions][drawables]") {
  CHECK(checked_for_name_comparisons("tools/pixel_formats.cpp"));
  CHECK(checked_for_name_comparisons("tools/playground/playground.js"));
  CHECK(checked_for_name_comparisons("fuzz/coverage_check.cpp"));
  CHECK_FALSE(checked_for_name_comparisons("tools/raster_test.cpp"));
  CHECK_FALSE(checked_for_name_comparisons("tests/hard_cases/hard_cases.cpp"));
  CHECK_FALSE(checked_for_name_comparisons("fuzz/regressions/fuzz_regressions_test.cpp"));
  CHECK_FALSE(checked_for_name_comparisons("chapters/08_fast_exact/algorithms.cpp"));
  CHECK_FALSE(checked_for_name_comparisons("build/release/x.cpp"));
  CHECK_FALSE(checked_for_name_comparisons("README.md"));
}

TEST_CASE(
    "No source outside the registrations and the tests compares a string with a registered name",
    "[conventions][drawables]") {
  const fs::path root = TUTORIAL_SOURCE_DIR;
  // The book's drawables and the peers this build has: a peer is asked what it declares too.
  std::vector<Drawable> drawables = registered_drawables();
  for (const ExternalPeer& peer : external_peers()) drawables.push_back(peer);
  for (const CoveragePeer& peer : coverage_peers()) drawables.push_back(peer);
  const auto names = registered_names(drawables);
  REQUIRE(names.size() == drawables.size());
  std::size_t checked = 0;
  for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator();
       ++it) {
    const fs::path relative = fs::relative(it->path(), root);
    const std::string top = relative.begin()->string();
    if (it->is_directory() && (top == "build" || top.starts_with("."))) {
      it.disable_recursion_pending();
      continue;
    }
    if (!it->is_regular_file() || !checked_for_name_comparisons(relative)) continue;
    ++checked;
    for (const NameComparison& c : name_comparisons(read(it->path()), names)) {
      FAIL_CHECK(relative.generic_string() << ':' << c.line << " compares with the registered name "
                                           << c.name << ": ask the drawable what it declares");
    }
  }
  CHECK(checked > 100);  // the walk reached the sources
}

}  // namespace
}  // namespace tri::conventions
