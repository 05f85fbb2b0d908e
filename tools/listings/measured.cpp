#include "tools/listings/measured.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>

#include "measure/number_format.hpp"
#include "tools/listings/markdown_syntax.hpp"

namespace tri::listings {

namespace {

constexpr std::string_view kRatio = "ratio:";
constexpr std::string_view kHeader = "header:";

// The number a KEY names in a snapshot, or an explanation of why there is none.
struct Lookup {
  std::optional<double> value;
  std::string missing;
};

Lookup look_up(const Snapshot& snapshot, std::string_view key, const std::string& file) {
  const auto one = [&](std::string_view k) -> Lookup {
    if (const auto it = snapshot.numbers.find(k); it != snapshot.numbers.end()) {
      return {it->second, {}};
    }
    if (snapshot.texts.contains(k)) {
      return {std::nullopt, "key '" + std::string(k) + "' of " + file + " is text, not a number"};
    }
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

// The text a marker shows: a header line, a text key, or a number in FORMAT.
struct Shown {
  std::optional<std::string> text;
  std::string missing;
};

Shown shown_value(const Snapshot& snapshot, std::string_view key, std::string_view format,
                  const std::string& file) {
  const auto as_text = [&](const auto& texts, std::string_view name,
                           const std::string& what) -> Shown {
    if (!format.empty())
      return {std::nullopt, what + " '" + std::string(name) + "' takes no format"};
    if (const auto it = texts.find(name); it != texts.end()) return {it->second, {}};
    return {std::nullopt, what + " '" + std::string(name) + "' is not in " + file};
  };
  if (key.starts_with(kHeader))
    return as_text(snapshot.header, key.substr(kHeader.size()), "header");
  if (snapshot.texts.contains(key)) return as_text(snapshot.texts, key, "key");
  const Lookup found = look_up(snapshot, key, file);
  if (!found.value) return {std::nullopt, found.missing};
  auto text = format_measured(*found.value, format);
  if (!text) {
    return {std::nullopt,
            "format '" + std::string(format) + "' is not sN or fN with an optional suffix"};
  }
  return {std::move(text), {}};
}

// True when the text before `position` holds an odd number of backticks: inside inline code.
bool inside_inline_code(std::string_view line, std::size_t position) {
  return std::count(line.begin(), line.begin() + static_cast<std::ptrdiff_t>(position), '`') % 2 ==
         1;
}

}  // namespace

std::optional<std::vector<std::string>> measured_table(const Snapshot& snapshot,
                                                       std::string_view name,
                                                       std::string& missing) {
  if (name != "summary") {
    missing = "table '" + std::string(name) + "' is not one the tool writes (summary)";
    return std::nullopt;
  }
  std::vector<std::string> lines{
      "| algorithm | chapter | Mpix/s large | tris/s tiny | tris/s mesh | Mpix/s all | error rate "
      "|",
      "|---|---|--:|--:|--:|--:|--:|"};
  constexpr std::string_view kChapter = ".chapter";
  for (const std::string& key : snapshot.keys) {
    if (!key.ends_with(kChapter)) continue;
    const std::string algorithm = key.substr(0, key.size() - kChapter.size());
    const auto number = [&](const std::string& metric) -> std::optional<double> {
      const auto it = snapshot.numbers.find(algorithm + "." + metric);
      if (it == snapshot.numbers.end()) {
        missing = "key '" + algorithm + "." + metric + "' is not a number of the snapshot";
        return std::nullopt;
      }
      return it->second;
    };
    const auto threaded = number("threaded");
    const auto large = number("large_mpix_per_s");
    const auto tiny = number("tiny_tris_per_s");
    const auto mesh = number("mesh_tris_per_s");
    const auto all = number("mpix_per_s");
    const auto error = number("error_rate");
    if (!threaded || !large || !tiny || !mesh || !all || !error) return std::nullopt;
    lines.push_back("| `" + algorithm + "`" + (*threaded != 0 ? " (threaded)" : "") + " | " +
                    snapshot.texts.at(key) + " | " + format_mpix(*large) + " | " +
                    human_rate(*tiny) + " | " + human_rate(*mesh) + " | " + format_mpix(*all) +
                    " | " + format_error_rate(*error) + " |");
  }
  if (lines.size() == 2) {
    missing = "the snapshot has no algorithm (no KEY.chapter line)";
    return std::nullopt;
  }
  return lines;
}

std::optional<std::string> format_measured(double value, std::string_view format) {
  if (format.empty()) format = "s3";
  if (format.size() < 2 || (format[0] != 's' && format[0] != 'f')) return std::nullopt;
  int digits = 0;
  const auto* first = format.data() + 1;
  const auto [end, error] = std::from_chars(first, format.data() + format.size(), digits);
  if (error != std::errc() || digits < 0 || digits > 12) return std::nullopt;
  const std::string_view suffix(end, format.data() + format.size() - end);
  if (format[0] == 's' && digits == 0) return std::nullopt;
  // Digits left of the point are always kept (12345 stays 12345, never 1.23e+04).
  const int whole_digits =
      value == 0 ? 1 : static_cast<int>(std::floor(std::log10(std::fabs(value)))) + 1;
  const int significant =
      format[0] == 's' ? std::max(digits, whole_digits) : std::max(1, whole_digits + digits);
  return format_number(value, significant) + std::string(suffix);
}

const Snapshot* SnapshotCache::find(const std::string& file) {
  if (const auto it = files_.find(file); it != files_.end()) {
    return it->second ? &*it->second : nullptr;
  }
  std::optional<Snapshot> snapshot;
  try {
    snapshot = read_snapshot(root_ / file);
  } catch (const std::runtime_error&) {
    // Missing or not a snapshot: its markers are reported as such.
  }
  const auto& stored = files_.emplace(file, std::move(snapshot)).first->second;
  return stored ? &*stored : nullptr;
}

namespace {

// The block of table lines opened at lines[open] checked against its snapshot and rewritten from
// it; returns the index of its closing line (or of the opening line when it is malformed).
std::size_t fill_table(const std::string& name, std::vector<std::string>& lines, std::size_t open,
                       SnapshotCache& snapshots, std::vector<Problem>& problems) {
  const int line_number = static_cast<int>(open) + 1;
  const auto add = [&](int at, const std::string& message, bool refreshable = false) {
    problems.push_back({name, at, message, refreshable});
  };
  const std::string_view head = trimmed_start(lines[open]);
  std::istringstream words{std::string(head.substr(kMeasuredTableOpen.size()))};
  std::string file, table, end;
  std::size_t close = open + 1;
  while (close < lines.size() && trimmed_start(lines[close]) != kMeasuredTableClose) ++close;
  if (!(words >> file >> table >> end) || end != kCommentEnd || close == lines.size()) {
    add(line_number,
        "malformed measured table; write <!-- measured-table: FILE TABLE --> on a "
        "line, then the table, then <!-- /measured-table --> on a line");
    return open;
  }
  const Snapshot* snapshot = snapshots.find(file);
  if (snapshot == nullptr) {
    add(line_number, "measured table names " + file + ", which is missing or not a snapshot");
    return close;
  }
  std::string missing;
  const auto table_lines = measured_table(*snapshot, table, missing);
  if (!table_lines) {
    add(line_number, "measured table: " + missing);
    return close;
  }
  const auto first = lines.begin() + static_cast<std::ptrdiff_t>(open + 1);
  const auto last = lines.begin() + static_cast<std::ptrdiff_t>(close);
  if (std::equal(first, last, table_lines->begin(), table_lines->end())) return close;
  const auto differs = std::mismatch(first, last, table_lines->begin(), table_lines->end());
  const int at = static_cast<int>(differs.first - lines.begin()) + 1;
  add(at,
      "measured table line '" + (differs.first == last ? std::string("(none)") : *differs.first) +
          "' differs from '" +
          (differs.second == table_lines->end() ? std::string("(none)") : *differs.second) + "' (" +
          table + " of " + file + "); refresh with: " + std::string(kMeasuredRefreshCommand),
      true);
  lines.erase(first, last);
  lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(open + 1), table_lines->begin(),
               table_lines->end());
  return open + 1 + table_lines->size();
}

}  // namespace

int fill_measured(const std::string& name, std::vector<std::string>& lines,
                  SnapshotCache& snapshots, std::vector<Problem>& problems) {
  int markers = 0;
  FencedBlocks fences;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    std::string& line = lines[i];
    const int line_number = static_cast<int>(i) + 1;
    if (fences.is_code(trimmed_start(line))) continue;
    if (trimmed_start(line).starts_with(kMeasuredTableOpen)) {
      ++markers;
      i = fill_table(name, lines, i, snapshots, problems);
      continue;
    }
    for (auto open = line.find(kMeasuredOpen); open != std::string::npos;
         open = line.find(kMeasuredOpen, open + 1)) {
      if (inside_inline_code(line, open)) continue;
      ++markers;
      const auto add = [&](const std::string& message, bool refreshable = false) {
        problems.push_back({name, line_number, message, refreshable});
      };
      const auto end = line.find(kCommentEnd, open);
      const auto close = end == std::string::npos ? end : line.find(kMeasuredClose, end);
      if (close == std::string::npos) {
        add("malformed measured marker; write <!-- measured: FILE KEY [FORMAT] -->value"
            "<!-- /measured --> on one line");
        continue;
      }
      std::istringstream words{
          line.substr(open + kMeasuredOpen.size(), end - open - kMeasuredOpen.size())};
      std::string file, key, format, extra;
      if (!(words >> file >> key) || (words >> format && words >> extra)) {
        add("malformed measured marker; write <!-- measured: FILE KEY [FORMAT] -->");
        continue;
      }
      const Snapshot* snapshot = snapshots.find(file);
      if (snapshot == nullptr) {
        add("measured marker names " + file + ", which is missing or not a snapshot");
        continue;
      }
      const Shown shown = shown_value(*snapshot, key, format, file);
      if (!shown.text) {
        add("measured marker: " + shown.missing);
        continue;
      }
      const auto value_begin = end + kCommentEnd.size();
      const std::string_view current(line.data() + value_begin, close - value_begin);
      if (current != *shown.text) {
        add("measured value " + std::string(current) + " differs from " + *shown.text + " (" + key +
                " in " + file + "); refresh with: " + std::string(kMeasuredRefreshCommand),
            true);
        line.replace(value_begin, close - value_begin, *shown.text);
      }
    }
  }
  return markers;
}

}  // namespace tri::listings
