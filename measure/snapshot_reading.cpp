#include "measure/snapshot_reading.hpp"

#include <charconv>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace tri {
namespace {

std::runtime_error bad_line(int number, std::string_view why) {
  return std::runtime_error("snapshot line " + std::to_string(number) + ": " + std::string(why));
}

}  // namespace

std::string Snapshot::header_text(std::string_view name) const {
  const auto found = header.find(name);
  return found == header.end() ? "unknown" : found->second;
}

std::optional<double> Snapshot::number(std::string_view key) const {
  const auto found = numbers.find(key);
  if (found == numbers.end()) return std::nullopt;
  return found->second;
}

Snapshot parse_snapshot(std::string_view text) {
  Snapshot snapshot;
  bool seen_columns = false;
  std::istringstream lines{std::string(text)};
  int number = 0;
  for (std::string line; std::getline(lines, line);) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    if (line.front() == '#') {
      // "# name: text", a name without spaces; the title line ("# Measurement snapshot ...") has
      // none.
      const auto colon = line.find(": ");
      if (line.starts_with("# ") && colon != std::string::npos && line.find(' ', 2) >= colon) {
        snapshot.header.insert_or_assign(line.substr(2, colon - 2), line.substr(colon + 2));
      }
      continue;
    }
    if (!seen_columns) {
      if (line != "key,value") throw bad_line(number, "expected the column line key,value");
      seen_columns = true;
      continue;
    }
    const auto comma = line.find(',');
    if (comma == std::string::npos) throw bad_line(number, "no comma");
    std::string key = line.substr(0, comma);
    const std::string value = line.substr(comma + 1);
    if (key.empty()) throw bad_line(number, "no key");
    if (value.empty()) throw bad_line(number, "no value");
    double parsed = 0;
    const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), parsed);
    if (error == std::errc() && end == value.data() + value.size()) {
      snapshot.numbers.insert_or_assign(key, parsed);
    } else {
      snapshot.texts.insert_or_assign(key, value);
    }
    snapshot.keys.push_back(std::move(key));
  }
  if (!seen_columns) throw std::runtime_error("not a snapshot: no line key,value");
  return snapshot;
}

Snapshot read_snapshot(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read the snapshot " + file.string());
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  try {
    return parse_snapshot(text);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(file.string() + ": " + e.what());
  }
}

}  // namespace tri
