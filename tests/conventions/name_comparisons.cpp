#include "tests/conventions/name_comparisons.hpp"

#include <algorithm>
#include <array>

namespace tri::conventions {
namespace {

int line_of(std::string_view source, std::size_t offset) {
  return 1 + static_cast<int>(std::count(source.begin(), source.begin() + offset, '\n'));
}

// The text before `at` with trailing spaces dropped.
std::string_view before(std::string_view source, std::size_t at) {
  std::string_view text = source.substr(0, at);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t')) text.remove_suffix(1);
  return text;
}

// The text from `at` with leading spaces dropped.
std::string_view after(std::string_view source, std::size_t at) {
  std::string_view text = source.substr(at);
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  return text;
}

// Whether the quoted literal that starts at `open` and ends before `close` is compared.
bool compared(std::string_view source, std::size_t open, std::size_t close) {
  const std::string_view left = before(source, open);
  const std::string_view right = after(source, close + 1);
  for (const std::string_view op : {"==", "!=", "===", "!==", "starts_with(", "ends_with("}) {
    if (left.ends_with(op)) return true;
  }
  for (const std::string_view op : {"==", "!="}) {
    if (right.starts_with(op)) return true;
  }
  // `= "NAME";`: a constant holding the name, compared with elsewhere.
  return left.ends_with("=") && !left.ends_with("==") && right.starts_with(";");
}

}  // namespace

std::vector<NameComparison> name_comparisons(std::string_view source,
                                             std::span<const std::string_view> names) {
  std::vector<NameComparison> found;
  for (const std::string_view name : names) {
    for (const char quote : {'"', '\''}) {
      const std::string literal = quote + std::string(name) + quote;
      for (std::size_t at = source.find(literal); at != std::string_view::npos;
           at = source.find(literal, at + 1)) {
        if (compared(source, at, at + literal.size() - 1))
          found.push_back({std::string(name), line_of(source, at)});
      }
    }
  }
  std::sort(found.begin(), found.end(),
            [](const NameComparison& a, const NameComparison& b) { return a.line < b.line; });
  return found;
}

bool checked_for_name_comparisons(const std::filesystem::path& relative) {
  const std::string path = relative.generic_string();
  const std::string file = relative.filename().string();
  constexpr std::array sources{".cpp", ".hpp", ".js"};
  if (std::none_of(sources.begin(), sources.end(),
                   [&](const char* ext) { return file.ends_with(ext); })) {
    return false;
  }
  for (const std::string_view skipped : {"build", ".git", "tests/", "fuzz/regressions/"}) {
    if (path.starts_with(skipped)) return false;
  }
  return !file.ends_with("_test.cpp") && file != "algorithms.cpp" && file != "area_algorithms.cpp";
}

}  // namespace tri::conventions
