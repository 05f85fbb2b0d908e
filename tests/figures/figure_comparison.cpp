#include "tests/figures/figure_comparison.hpp"

#include <stb_image.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <memory>
#include <regex>
#include <set>

namespace tri::figures {
namespace fs = std::filesystem;
namespace {

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

struct DecodedImage {
  int width = 0, height = 0;
  std::unique_ptr<unsigned char, void (*)(void*)> pixels{nullptr, stbi_image_free};
};

DecodedImage decode_png(const std::string& bytes) {
  DecodedImage image;
  int channels = 0;
  image.pixels.reset(stbi_load_from_memory(reinterpret_cast<const unsigned char*>(bytes.data()),
                                           static_cast<int>(bytes.size()), &image.width,
                                           &image.height, &channels, 4));
  return image;
}

// Where two PNG images first differ, in the tutorial's pixel coordinates (y up), or "".
std::string png_difference(const std::string& rendered, const std::string& committed) {
  const DecodedImage a = decode_png(rendered), b = decode_png(committed);
  if (!a.pixels || !b.pixels) return "cannot be decoded as PNG";
  if (a.width != b.width || a.height != b.height) {
    return "is " + std::to_string(a.width) + "x" + std::to_string(a.height) +
           " pixels, the "
           "committed one " +
           std::to_string(b.width) + "x" + std::to_string(b.height);
  }
  const auto size = static_cast<std::size_t>(a.width) * static_cast<std::size_t>(a.height) * 4;
  const auto [pa, pb] = std::mismatch(a.pixels.get(), a.pixels.get() + size, b.pixels.get());
  if (pa == a.pixels.get() + size) return "";
  const auto pixel = static_cast<std::size_t>(pa - a.pixels.get()) / 4;
  const auto x = static_cast<int>(pixel % static_cast<std::size_t>(a.width));
  const auto row_from_top = static_cast<int>(pixel / static_cast<std::size_t>(a.width));
  std::size_t count = 0;
  for (std::size_t i = 0; i < size; i += 4) {
    if (!std::equal(a.pixels.get() + i, a.pixels.get() + i + 4, b.pixels.get() + i)) ++count;
  }
  return "differs in " + std::to_string(count) + " pixel(s), first at image pixel (" +
         std::to_string(x) + ", " + std::to_string(a.height - 1 - row_from_top) +
         ") counted "
         "from the bottom-left";
}

// The first line where two texts differ, or "".
std::string text_difference(const std::string& rendered, const std::string& committed) {
  if (rendered == committed) return "";
  const auto [ra, ca] =
      std::mismatch(rendered.begin(), rendered.end(), committed.begin(), committed.end());
  const auto line = 1 + std::count(rendered.begin(), ra, '\n');
  return "differs from the committed file at byte " + std::to_string(ra - rendered.begin()) +
         " (line " + std::to_string(line) + ")";
}

std::vector<fs::path> regular_files(const fs::path& folder) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(folder)) {
    if (entry.is_regular_file()) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

std::vector<std::string> compare_figures(const fs::path& rendered, const fs::path& committed) {
  std::vector<std::string> problems;
  for (const auto& file : regular_files(rendered)) {
    const fs::path name = file.filename();
    const fs::path expected = committed / name;
    if (!fs::is_regular_file(expected)) {
      problems.push_back(name.string() + ": rendered but not committed in " + committed.string());
      continue;
    }
    const std::string a = read_bytes(file), b = read_bytes(expected);
    const std::string difference =
        file.extension() == ".png" ? png_difference(a, b) : text_difference(a, b);
    if (!difference.empty()) problems.push_back(name.string() + ": " + difference);
  }
  return problems;
}

std::vector<std::string> stale_figures(const fs::path& committed,
                                       const std::vector<fs::path>& rendered_folders,
                                       const std::vector<std::string>& snapshots) {
  std::set<std::string> rendered(snapshots.begin(), snapshots.end());
  for (const auto& folder : rendered_folders) {
    for (const auto& file : regular_files(folder)) rendered.insert(file.filename().string());
  }
  std::vector<std::string> problems;
  for (const auto& file : regular_files(committed)) {
    const std::string name = file.filename().string();
    if (!rendered.contains(name)) {
      problems.push_back(name + ": committed in " + committed.string() +
                         " but no program renders it (delete it, or render it again)");
    }
  }
  return problems;
}

std::vector<std::string> missing_images(const fs::path& repository_root,
                                        const std::vector<fs::path>& markdown_files) {
  // ![alt](target) or ![alt](target "title"); alt text may hold anything but a closing bracket.
  static const std::regex image(R"(!\[[^\]]*\]\(\s*([^)\s]+)(\s+"[^"]*")?\s*\))");
  const fs::path root = fs::weakly_canonical(repository_root);
  std::vector<std::string> problems;
  for (const auto& markdown : markdown_files) {
    std::ifstream in(markdown);
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
      for (std::sregex_iterator it(line.begin(), line.end(), image), end; it != end; ++it) {
        const std::string target = (*it)[1];
        const std::string where = markdown.string() + ":" + std::to_string(number) + ": ";
        if (target.starts_with("http:") || target.starts_with("https:")) {
          problems.push_back(where + target + " is not a file of the repository");
          continue;
        }
        const fs::path resolved = fs::weakly_canonical(markdown.parent_path() / target);
        const auto relative = resolved.lexically_relative(root);
        if (relative.empty() || *relative.begin() == "..") {
          problems.push_back(where + target + " points outside the repository");
        } else if (!fs::is_regular_file(resolved)) {
          problems.push_back(where + target + " does not exist");
        }
      }
    }
  }
  return problems;
}

}  // namespace tri::figures
