#include "tools/listings/listings.hpp"

#include "tools/listings/markdown_syntax.hpp"
#include "tools/listings/measured.hpp"
#include "tools/listings/unmarked.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <sstream>
#include <utility>

namespace tri::listings {
namespace fs = std::filesystem;

namespace {

constexpr std::string_view kOpen = "// [listing ";
constexpr std::string_view kClose = "// [/listing]";
constexpr std::string_view kFenceOpen = "```cpp";

std::string_view trim(std::string_view s) {
  const auto is_space = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

bool is_region_name(std::string_view name) {
  return !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
  });
}

// The text split at '\n'; a final line without '\n' counts, an empty remainder does not.
std::vector<std::string> split_lines(std::string_view text) {
  std::vector<std::string> lines;
  while (!text.empty()) {
    const auto end = text.find('\n');
    if (end == std::string_view::npos) {
      lines.emplace_back(text);
      break;
    }
    lines.emplace_back(text.substr(0, end));
    text.remove_prefix(end + 1);
  }
  return lines;
}

// The lines with their common leading whitespace removed; blank lines become empty.
std::string dedent(const std::vector<std::string>& lines) {
  std::size_t indent = std::string::npos;
  for (const auto& line : lines) {
    if (trim(line).empty()) continue;
    indent = std::min(indent, line.find_first_not_of(" \t"));
  }
  std::string text;
  for (const auto& line : lines) {
    if (!trim(line).empty()) text.append(line, indent);
    text += '\n';
  }
  return text;
}

std::optional<std::string> read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

bool skipped_folder(const fs::path& folder) {
  const auto name = folder.filename().string();
  return name.empty() || name.front() == '.' || name == "build" || name == "out";
}

// Every regular file under root whose extension is one of `extensions`, outside build folders
// and hidden folders, sorted so that reports come in the same order on every machine.
std::vector<fs::path> files_under(const fs::path& root,
                                  const std::vector<std::string_view>& extensions) {
  std::vector<fs::path> files;
  for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator();
       ++it) {
    if (it->is_directory()) {
      if (skipped_folder(it->path())) it.disable_recursion_pending();
      continue;
    }
    if (!it->is_regular_file()) continue;
    const auto ext = it->path().extension().string();
    if (std::find(extensions.begin(), extensions.end(), ext) != extensions.end()) {
      files.push_back(it->path());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::string relative_name(const fs::path& path, const fs::path& root) {
  return path.lexically_relative(root).generic_string();
}

// The sources' markers, read once per file; problems of each file are reported once.
class SourceCache {
 public:
  explicit SourceCache(fs::path root) : root_(std::move(root)) {}

  // The markers of `name` (relative to the root), or nullptr when the file does not exist.
  const Markers* find(const std::string& name, std::vector<Problem>& problems) {
    if (const auto it = files_.find(name); it != files_.end()) {
      return it->second ? &*it->second : nullptr;
    }
    std::optional<Markers> markers;
    if (const auto text = read_file(root_ / name)) {
      markers = parse_markers(*text, name);
      problems.insert(problems.end(), markers->problems.begin(), markers->problems.end());
    }
    const auto& stored = files_.emplace(name, std::move(markers)).first->second;
    return stored ? &*stored : nullptr;
  }

 private:
  fs::path root_;
  std::map<std::string, std::optional<Markers>> files_;
};

std::string refresh_hint() {
  return "; refresh with: " + std::string(kRefreshCommand);
}

// What a listing comment names.
struct ListingComment {
  std::string file;
  std::string region;
};

std::optional<ListingComment> parse_comment(std::string_view line) {
  line = trim(line);
  if (!line.starts_with(kListingOpen) || !line.ends_with(kCommentEnd)) return std::nullopt;
  line.remove_prefix(kListingOpen.size());
  line.remove_suffix(kCommentEnd.size());
  std::istringstream words{std::string(line)};
  ListingComment comment;
  std::string extra;
  if (!(words >> comment.file >> comment.region) || (words >> extra)) return std::nullopt;
  return comment;
}

bool safe_relative_path(const std::string& name) {
  const fs::path path(name);
  if (path.is_absolute()) return false;
  return std::none_of(path.begin(), path.end(), [](const fs::path& part) { return part == ".."; });
}

// One Markdown file's listings: each checked against its region, and the file's lines copied to
// `out_lines` with every listing that has a region rewritten from it.
void process_markdown(const std::string& name, const std::string& text, SourceCache& sources,
                      Report& report, std::vector<std::string>& out_lines) {
  const auto lines = split_lines(text);
  FencedBlocks fences;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string& line = lines[i];
    const auto trimmed = trim(line);
    const int line_number = static_cast<int>(i) + 1;
    if (fences.is_code(trimmed) || !trimmed.starts_with(kListingOpen)) {
      out_lines.push_back(line);
      continue;
    }
    out_lines.push_back(line);
    ++report.listings;
    const auto comment = parse_comment(line);
    if (!comment || !is_region_name(comment->region) || !safe_relative_path(comment->file)) {
      report.problems.push_back({name, line_number,
                                 "malformed listing comment; write <!-- listing: "
                                 "path/from/root.cpp region_name -->"});
      continue;
    }
    // The block that follows, if any: lines [body_begin, body_end), then the closing fence.
    const bool has_block = i + 1 < lines.size() && trim(lines[i + 1]) == kFenceOpen;
    std::size_t body_begin = i + 2;
    std::size_t body_end = body_begin;
    if (has_block) {
      while (body_end < lines.size() && trim(lines[body_end]) != kFence) ++body_end;
      if (body_end == lines.size()) {
        report.problems.push_back(
            {name, line_number + 1, "the ```cpp block of this listing is never closed"});
        continue;
      }
    }
    const auto where = comment->file + " region '" + comment->region + "'";
    const Markers* markers = sources.find(comment->file, report.problems);
    const Region* region = nullptr;
    if (markers == nullptr) {
      report.problems.push_back(
          {name, line_number, "listing names " + comment->file + ", which does not exist"});
    } else {
      const auto it = std::find_if(markers->regions.begin(), markers->regions.end(),
                                   [&](const Region& r) { return r.name == comment->region; });
      if (it == markers->regions.end()) {
        report.problems.push_back({name, line_number,
                                   "listing names region '" + comment->region + "', which " +
                                       comment->file + " does not mark (// [listing " +
                                       comment->region + "] ... // [/listing])"});
      } else {
        region = &*it;
      }
    }
    std::vector<std::string> body;
    if (has_block) body.assign(lines.begin() + body_begin, lines.begin() + body_end);
    if (region == nullptr) {
      // Left as it is: nothing to refresh it from.
      if (has_block) {
        out_lines.insert(out_lines.end(), lines.begin() + i + 1, lines.begin() + body_end + 1);
        i = body_end;
      }
      continue;
    }
    if (!has_block) {
      report.problems.push_back(
          {name, line_number,
           "listing of " + where + " is not followed by a ```cpp block" + refresh_hint(), true});
    } else {
      std::string shown;
      for (const auto& body_line : body) shown += body_line + '\n';
      if (shown != region->text) {
        report.problems.push_back({name, line_number,
                                   "listing differs from " + where + " (marked at line " +
                                       std::to_string(region->first_line) + ")" + refresh_hint(),
                                   true});
      }
      i = body_end;
    }
    out_lines.emplace_back(kFenceOpen);
    for (const auto& region_line : split_lines(region->text)) out_lines.push_back(region_line);
    out_lines.emplace_back(kFence);
  }
}

Report run(const fs::path& root, bool write) {
  Report report;
  SourceCache sources(root);
  SnapshotCache snapshots(root);
  // Every source's markers must balance, whether a README shows them or not.
  for (const auto& source : files_under(root, {".cpp", ".hpp", ".h"})) {
    sources.find(relative_name(source, root), report.problems);
  }
  for (const auto& markdown : files_under(root, {".md"})) {
    const auto name = relative_name(markdown, root);
    const auto text = read_file(markdown);
    if (!text) {
      report.problems.push_back({name, 0, "cannot be read"});
      continue;
    }
    std::vector<std::string> out_lines;
    Report found;
    process_markdown(name, *text, sources, found, out_lines);
    report.listings += found.listings;
    report.measured += fill_measured(name, out_lines, snapshots, found.problems);
    if (quotes_measurements(name)) find_unmarked_measurements(name, out_lines, found.problems);
    for (auto& problem : found.problems) {
      // --update fixes the listings that differ or lack their block; the rest stay reported.
      if (!write || !problem.refreshable) {
        report.problems.push_back(std::move(problem));
      }
    }
    if (!write) continue;
    std::string new_text;
    for (const auto& out_line : out_lines) new_text += out_line + '\n';
    if (!text->empty() && text->back() != '\n' && !new_text.empty()) new_text.pop_back();
    if (new_text != *text) {
      std::ofstream out(markdown, std::ios::binary | std::ios::trunc);
      out << new_text;
      if (!out) {
        report.problems.push_back({name, 0, "cannot be written"});
        continue;
      }
      report.rewritten.push_back(name);
    }
  }
  return report;
}

}  // namespace

std::string format(const Problem& problem) {
  return problem.file + ":" + std::to_string(problem.line) + ": " + problem.message;
}

Markers parse_markers(std::string_view text, const std::string& file) {
  Markers markers;
  const auto lines = split_lines(text);
  std::optional<Region> open;
  std::vector<std::string> body;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const int line_number = static_cast<int>(i) + 1;
    const auto line = trim(lines[i]);
    if (line.starts_with("// [/listing")) {
      if (line != kClose) {
        markers.problems.push_back({file, line_number, "malformed marker; write // [/listing]"});
      } else if (!open) {
        markers.problems.push_back(
            {file, line_number, "// [/listing] closes no region: no // [listing NAME] is open"});
      } else {
        if (body.empty()) {
          markers.problems.push_back(
              {file, open->first_line, "region '" + open->name + "' is empty"});
        }
        open->text = dedent(body);
        markers.regions.push_back(std::move(*open));
        open.reset();
        body.clear();
      }
      continue;
    }
    if (line.starts_with("// [listing")) {
      auto name = line;
      const bool well_formed = name.starts_with(kOpen) && name.ends_with("]");
      if (well_formed) {
        name.remove_prefix(kOpen.size());
        name.remove_suffix(1);
      }
      if (!well_formed || !is_region_name(name)) {
        markers.problems.push_back(
            {file, line_number, "malformed marker; write // [listing NAME], NAME of [A-Za-z0-9_]"});
        continue;
      }
      if (open) {
        markers.problems.push_back({file, line_number,
                                    "region '" + std::string(name) + "' opens inside region '" +
                                        open->name + "' (line " + std::to_string(open->first_line) +
                                        "); regions may not nest or overlap"});
        continue;
      }
      const auto same = std::find_if(markers.regions.begin(), markers.regions.end(),
                                     [&](const Region& r) { return r.name == name; });
      if (same != markers.regions.end()) {
        markers.problems.push_back({file, line_number,
                                    "region '" + std::string(name) +
                                        "' is marked twice (first at line " +
                                        std::to_string(same->first_line) + ")"});
      }
      open = Region{std::string(name), line_number, {}};
      continue;
    }
    if (open) body.push_back(lines[i]);
  }
  if (open) {
    markers.problems.push_back(
        {file, open->first_line, "region '" + open->name + "' is never closed by // [/listing]"});
  }
  return markers;
}

Report check_listings(const fs::path& root) {
  return run(root, false);
}

Report update_listings(const fs::path& root) {
  return run(root, true);
}

}  // namespace tri::listings
