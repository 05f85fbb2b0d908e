#include "tools/listings/measured.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <sstream>

namespace tri::listings {

namespace {

constexpr std::string_view kMarkerOpen = "<!-- measured:";
constexpr std::string_view kMarkerEnd = "-->";
constexpr std::string_view kMarkerClose = "<!-- /measured -->";
constexpr std::string_view kRatio = "ratio:";

using Numbers = std::map<std::string, double, std::less<>>;

std::optional<double> parse_number(std::string_view text) {
  double value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

// The number a KEY names in a snapshot, or an explanation of why there is none.
struct Lookup {
  std::optional<double> value;
  std::string missing;
};

Lookup look_up(const Numbers& numbers, std::string_view key, const std::string& file) {
  const auto one = [&](std::string_view k) -> Lookup {
    if (const auto it = numbers.find(k); it != numbers.end()) return {it->second, {}};
    return {std::nullopt, "key '" + std::string(k) + "' is not in " + file};
  };
  if (!key.starts_with(kRatio)) return one(key);
  key.remove_prefix(kRatio.size());
  const auto slash = key.find('/');
  if (slash == std::string_view::npos) {
    return {std::nullopt, "a ratio is written ratio:KEY_A/KEY_B"};
  }
  const auto top = one(key.substr(0, slash));
  if (!top.value) return top;
  const auto bottom = one(key.substr(slash + 1));
  if (!bottom.value) return bottom;
  if (*bottom.value == 0) return {std::nullopt, "the ratio divides by zero"};
  return {*top.value / *bottom.value, {}};
}

// True when the text before `position` holds an odd number of backticks: inside inline code.
bool inside_inline_code(std::string_view line, std::size_t position) {
  return std::count(line.begin(), line.begin() + static_cast<std::ptrdiff_t>(position), '`') % 2 ==
         1;
}

}  // namespace

std::optional<Numbers> parse_snapshot(std::string_view text) {
  Numbers numbers;
  bool seen_columns = false;
  std::istringstream lines{std::string(text)};
  for (std::string line; std::getline(lines, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line.front() == '#') continue;
    if (!seen_columns) {
      if (line != "key,value") return std::nullopt;
      seen_columns = true;
      continue;
    }
    const auto comma = line.find(',');
    if (comma == std::string::npos) return std::nullopt;
    const auto value = parse_number(std::string_view(line).substr(comma + 1));
    if (!value) return std::nullopt;
    numbers.insert_or_assign(line.substr(0, comma), *value);
  }
  if (!seen_columns) return std::nullopt;
  return numbers;
}

std::optional<std::string> format_measured(double value, std::string_view format) {
  if (format.empty()) format = "s3";
  if (format.size() < 2 || (format[0] != 's' && format[0] != 'f')) return std::nullopt;
  int digits = 0;
  const auto* first = format.data() + 1;
  const auto [end, error] = std::from_chars(first, format.data() + format.size(), digits);
  if (error != std::errc() || digits < 0 || digits > 12) return std::nullopt;
  const std::string_view suffix(end, format.data() + format.size() - end);
  int decimals = digits;
  if (format[0] == 's') {
    if (digits == 0) return std::nullopt;
    // Decimals that leave `digits` significant ones; never fewer than none (12345 stays 12345).
    const int magnitude =
        value == 0 ? 0 : static_cast<int>(std::floor(std::log10(std::fabs(value))));
    decimals = std::max(0, digits - 1 - magnitude);
  }
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return std::string(text) + std::string(suffix);
}

const Numbers* SnapshotCache::find(const std::string& file) {
  if (const auto it = files_.find(file); it != files_.end()) {
    return it->second ? &*it->second : nullptr;
  }
  std::optional<Numbers> numbers;
  if (std::ifstream in(root_ / file, std::ios::binary); in) {
    numbers = parse_snapshot(
        std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()));
  }
  const auto& stored = files_.emplace(file, std::move(numbers)).first->second;
  return stored ? &*stored : nullptr;
}

int fill_measured(const std::string& name, std::vector<std::string>& lines,
                  SnapshotCache& snapshots, std::vector<Problem>& problems) {
  int markers = 0;
  bool in_fence = false;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    std::string& line = lines[i];
    const int line_number = static_cast<int>(i) + 1;
    if (line.find_first_not_of(" \t") != std::string::npos &&
        std::string_view(line).substr(line.find_first_not_of(" \t")).starts_with("```")) {
      in_fence = !in_fence;
      continue;
    }
    if (in_fence) continue;
    for (auto open = line.find(kMarkerOpen); open != std::string::npos;
         open = line.find(kMarkerOpen, open + 1)) {
      if (inside_inline_code(line, open)) continue;
      ++markers;
      const auto add = [&](const std::string& message, bool refreshable = false) {
        problems.push_back({name, line_number, message, refreshable});
      };
      const auto end = line.find(kMarkerEnd, open);
      const auto close = end == std::string::npos ? end : line.find(kMarkerClose, end);
      if (close == std::string::npos) {
        add("malformed measured marker; write <!-- measured: FILE KEY [FORMAT] -->value"
            "<!-- /measured --> on one line");
        continue;
      }
      std::istringstream words{
          line.substr(open + kMarkerOpen.size(), end - open - kMarkerOpen.size())};
      std::string file, key, format, extra;
      if (!(words >> file >> key) || (words >> format && words >> extra)) {
        add("malformed measured marker; write <!-- measured: FILE KEY [FORMAT] -->");
        continue;
      }
      const Numbers* numbers = snapshots.find(file);
      if (numbers == nullptr) {
        add("measured marker names " + file + ", which is missing or not a snapshot");
        continue;
      }
      const Lookup found = look_up(*numbers, key, file);
      if (!found.value) {
        add("measured marker: " + found.missing);
        continue;
      }
      const auto shown = format_measured(*found.value, format);
      if (!shown) {
        add("measured marker: format '" + format + "' is not sN or fN with an optional suffix");
        continue;
      }
      const auto value_begin = end + kMarkerEnd.size();
      const std::string_view current(line.data() + value_begin, close - value_begin);
      if (current != *shown) {
        add("measured value " + std::string(current) + " differs from " + *shown + " (" + key +
                " in " + file + "); refresh with: " + std::string(kMeasuredRefreshCommand),
            true);
        line.replace(value_begin, close - value_begin, *shown);
      }
    }
  }
  return markers;
}

}  // namespace tri::listings
