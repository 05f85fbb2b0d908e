// listings_tool: checks or refreshes the code listings of the Markdown files (see listings.hpp).
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string_view>

#include "tools/listings/listings.hpp"

namespace {

constexpr std::string_view kUsage =
    "Usage: listings_tool --check ROOT | --update ROOT\n"
    "  --check ROOT   fail when a listing in a Markdown file under ROOT differs from the source\n"
    "                 region it names, names a missing file or region, or when markers do not\n"
    "                 balance (// [listing NAME] ... // [/listing]), or when a measured number\n"
    "                 (<!-- measured: FILE KEY [FORMAT] -->value<!-- /measured -->) differs\n"
    "                 from its snapshot or names a missing snapshot or key\n"
    "  --update ROOT  rewrite every listing from its region and every measured number from\n"
    "                 its snapshot\n";

int run(std::string_view mode, const std::filesystem::path& root) {
  namespace ls = tri::listings;
  const bool update = mode == "--update";
  const auto report = update ? ls::update_listings(root) : ls::check_listings(root);
  for (const auto& problem : report.problems) std::cerr << ls::format(problem) << '\n';
  for (const auto& file : report.rewritten) std::cout << "rewrote the listings of " << file << '\n';
  if (!report.problems.empty()) {
    std::cerr << report.problems.size() << " listing problem(s) in " << root.string() << '\n';
    return EXIT_FAILURE;
  }
  std::cout << report.listings << " listings and " << report.measured << " measured numbers "
            << (update ? "refreshed" : "match their sources and snapshots") << '\n';
  return EXIT_SUCCESS;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string_view mode = argc > 1 ? argv[1] : "";
  if (argc == 2 && (mode == "--help" || mode == "-h")) {
    std::cout << kUsage;
    return EXIT_SUCCESS;
  }
  if (argc != 3 || (mode != "--check" && mode != "--update")) {
    std::cerr << kUsage;
    return EXIT_FAILURE;
  }
  const std::filesystem::path root(argv[2]);
  if (!std::filesystem::is_directory(root)) {
    std::cerr << "listings_tool: " << root.string() << " is not a folder\n";
    return EXIT_FAILURE;
  }
  return run(mode, root);
}
