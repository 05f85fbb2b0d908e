#include "tools/listings/unmarked.hpp"

#include <regex>

#include "tools/listings/markdown_syntax.hpp"

namespace tri::listings {
namespace {

// A number not glued to a word before it (fixed_point_8, x86 and AVX2 hold no measurement).
constexpr const char* kNumber = R"((?:^|[^\w.])(\d+(?:[.,]\d+)*))";

// What follows a number that makes it a measurement: a ratio glued to it, or a unit.
const std::regex& measured_pattern() {
  static const std::regex pattern(
      std::string(kNumber) +
      "(?:"
      R"((?:×|x)(?![\w×]|\s*\d))"  // 3.2× or 3x, not 8×8, 8x8, 4 × 4 nor 0x1f
      R"(|(?:\s?(?:ns|µs|us|ms|sec|seconds?|minutes?|min)|\ss)(?![\w/'’-]))"  // times
      R"(|\s?(?:[kMG]\s?)?(?:pix|pixels?|px|tris|triangles|tri)/s)"           // rates
      R"(|\s?(?:Mpix|Mpixel|Mpixels|Gpix|Mtri|Mtris)\b)"
      R"(|\s?(?:[KMG]B/s|KiB|MiB|GiB)\b)"  // bandwidth and memory
      // a share of a speed, a time or a ceiling (not "22% of the light")
      R"(|\s?% of (?:(?:the|its|a|an|their) )?(?:\w+ )?(?:ceiling|peak|speed|rate|time|bandwidth|fastest|memset|run)\b)"
      R"(|\s+times (?:faster|slower|as fast)))");
  return pattern;
}

// A table header that names a measured unit: its numbers are measurements.
const std::regex& measured_header() {
  static const std::regex pattern(
      R"((?:Mpix|Mpixel|Mtri|tris/s|triangles/s|GB/s|MiB|\bns\b|µs|\bms\b|\bseconds?\b|speed-?up|× faster))");
  return pattern;
}

const std::regex& table_delimiter() {
  static const std::regex pattern(R"(^\s*\|?\s*:?-+:?\s*(\|\s*:?-+:?\s*)*\|?\s*$)");
  return pattern;
}

// The line without code spans, HTML comments (a marker with its value) and link targets.
std::string prose_of(const std::string& line) {
  std::string text;
  bool in_code = false;
  for (char c : line) {
    if (c == '`') {
      in_code = !in_code;
      continue;
    }
    if (!in_code) text += c;
  }
  static const std::regex marker(std::string(kMeasuredOpen) + ".*?" + std::string(kMeasuredClose));
  static const std::regex comment(R"(<!--.*?-->)");
  static const std::regex target(R"(\]\([^)]*\))");
  text = std::regex_replace(text, marker, " ");
  text = std::regex_replace(text, comment, " ");
  return std::regex_replace(text, target, "]");
}

}  // namespace

bool quotes_measurements(std::string_view name) {
  if (name == "README.md") return true;
  for (const std::string_view chapter : {"chapters/08_", "chapters/09_", "chapters/10_"}) {
    if (name.starts_with(chapter) && name.ends_with("/README.md") &&
        name.find('/', chapter.size()) == name.size() - std::string_view("/README.md").size()) {
      return true;
    }
  }
  return false;
}

std::optional<std::string> measured_looking(std::string_view prose) {
  std::match_results<std::string_view::const_iterator> match;
  if (!std::regex_search(prose.begin(), prose.end(), match, measured_pattern())) {
    return std::nullopt;
  }
  const auto text = match.str(0);
  const auto start = text.find_first_of("0123456789");
  return text.substr(start);
}

void find_unmarked_measurements(const std::string& name, const std::vector<std::string>& lines,
                                std::vector<Problem>& problems) {
  FencedBlocks fences;
  bool in_table_block = false;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string_view line = trimmed_start(lines[i]);
    const int line_number = static_cast<int>(i) + 1;
    if (fences.is_code(line)) continue;
    if (line.starts_with(kMeasuredTableOpen)) in_table_block = true;
    if (line.starts_with(kMeasuredTableClose)) in_table_block = false;
    if (in_table_block) continue;
    const std::string prose = prose_of(lines[i]);
    if (const auto found = measured_looking(prose)) {
      problems.push_back({name, line_number,
                          "'" + *found +
                              "' looks measured but is outside a measured marker; quote it from "
                              "a snapshot (docs/CONTRIBUTING.md) or state no measurement"});
    }
    const bool table_header = line.starts_with("|") && i + 1 < lines.size() &&
                              std::regex_match(lines[i + 1], table_delimiter());
    if (table_header && std::regex_search(prose, measured_header())) {
      problems.push_back({name, line_number,
                          "a table of measurements outside a measured table block "
                          "(<!-- measured-table: FILE TABLE -->, docs/CONTRIBUTING.md)"});
    }
  }
}

}  // namespace tri::listings
