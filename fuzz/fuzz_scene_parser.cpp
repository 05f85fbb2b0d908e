// libFuzzer target: every input is a scene text; parse_scene must return a scene within the
// format's limits or throw SceneError, and nothing else (see scene_parser_check.hpp).

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz/findings_abort.hpp"
#include "fuzz/scene_parser_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  tri::fuzz::abort_on_findings(tri::fuzz::check_scene_parser(text).findings);
  return 0;
}
