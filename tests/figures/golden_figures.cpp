// Renders every deterministic figure again and compares it with the one committed in
// docs/figures, so the READMEs can never show a figure the code no longer draws.
//
//   golden_figures --committed DIR --work DIR --program EXE [--program EXE ...]
//                  [--snapshot NAME ...] [--stale]
//   golden_figures --images ROOT MARKDOWN...
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <iostream>
#include <string>
#include <string_view>
#include <vector>

#include "tests/figures/figure_comparison.hpp"

namespace {
namespace fs = std::filesystem;

constexpr std::string_view refresh_hint =
    "The figures in docs/figures are committed copies of what the chapter programs render. If "
    "the change is intended, refresh them with\n"
    "  cmake --build --preset release --target refresh_figures\n"
    "then look at the new figures and commit them.";

// Runs `program --out folder` with its standard output discarded; true when it exited 0.
bool render(const fs::path& program, const fs::path& folder) {
  const pid_t child = fork();
  if (child < 0) return false;
  if (child == 0) {
    if (!freopen("/dev/null", "w", stdout)) _exit(127);
    const std::string path = program.string(), out = folder.string();
    execl(path.c_str(), path.c_str(), "--out", out.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  int status = 0;
  while (waitpid(child, &status, 0) < 0) {
  }
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

int report(const std::vector<std::string>& problems, std::string_view hint) {
  for (const auto& problem : problems) std::cerr << problem << "\n";
  if (problems.empty()) return 0;
  std::cerr << "\n" << hint << "\n";
  return 1;
}

int check_images(const std::vector<std::string>& args) {
  if (args.size() < 2) {
    std::cerr << "usage: golden_figures --images ROOT MARKDOWN...\n";
    return 2;
  }
  std::vector<fs::path> markdown(args.begin() + 1, args.end());
  const auto problems = tri::figures::missing_images(args[0], markdown);
  if (problems.empty()) std::cout << "every image of " << markdown.size() << " pages exists\n";
  return report(problems,
                "Every image a README shows must be a committed file (docs/figures), so the "
                "text reads complete in the repository view.");
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (!args.empty() && args[0] == "--images") {
    return check_images(std::vector<std::string>(args.begin() + 1, args.end()));
  }
  fs::path committed, work;
  std::vector<fs::path> programs;
  std::vector<std::string> snapshots;
  bool stale = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const bool has_value = i + 1 < args.size();
    if (args[i] == "--committed" && has_value) {
      committed = args[++i];
    } else if (args[i] == "--work" && has_value) {
      work = args[++i];
    } else if (args[i] == "--program" && has_value) {
      programs.emplace_back(args[++i]);
    } else if (args[i] == "--snapshot" && has_value) {
      snapshots.push_back(args[++i]);
    } else if (args[i] == "--stale") {
      stale = true;
    } else {
      std::cerr << "golden_figures: unexpected argument '" << args[i] << "'\n";
      return 2;
    }
  }
  if (committed.empty() || work.empty() || programs.empty()) {
    std::cerr << "usage: golden_figures --committed DIR --work DIR --program EXE... "
                 "[--snapshot NAME...] [--stale]\n";
    return 2;
  }
  std::vector<std::string> problems;
  std::vector<fs::path> rendered;
  for (const auto& program : programs) {
    const fs::path folder = work / program.filename();
    fs::remove_all(folder);
    fs::create_directories(folder);
    if (!render(program, folder)) {
      problems.push_back(program.string() + " --out " + folder.string() + " failed");
      continue;
    }
    rendered.push_back(folder);
    for (auto& problem : tri::figures::compare_figures(folder, committed)) {
      problems.push_back(program.filename().string() + ": " + problem);
    }
  }
  if (stale) {
    for (auto& problem : tri::figures::stale_figures(committed, rendered, snapshots)) {
      problems.push_back(std::move(problem));
    }
  }
  if (problems.empty()) {
    std::cout << "the figures of " << programs.size() << " program(s) equal the committed ones\n";
  }
  return report(problems, refresh_hint);
}
