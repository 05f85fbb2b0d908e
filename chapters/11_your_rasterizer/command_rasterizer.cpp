#include "chapters/11_your_rasterizer/command_rasterizer.hpp"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include "common/cli.hpp"
#include "common/image_io.hpp"
#include "common/printable_text.hpp"
#include "common/temporary_folder.hpp"
#include "measure/program_run.hpp"
#include "measure/scene_text.hpp"

namespace tri::conformance {
namespace {

namespace fs = std::filesystem;

// A private folder for the scene and counts files of one graded program, removed at the end.
class WorkFolder {
 public:
  const fs::path& path() const noexcept { return folder_.path(); }
  /// A new number for each run's files, so that nothing a killed run left behind is read again.
  int next_run() noexcept { return ++runs_; }

 private:
  TemporaryFolder folder_{"conformance"};
  int runs_ = 0;
};

std::string replaced(std::string word, std::string_view placeholder, const std::string& value) {
  for (auto at = word.find(placeholder); at != std::string::npos;
       at = word.find(placeholder, at + value.size())) {
    word.replace(at, placeholder.size(), value);
  }
  return word;
}

std::string signal_name(int signal) {
  const char* description = strsignal(signal);
  return "signal " + std::to_string(signal) +
         (description ? " (" + std::string(description) + ")" : "");
}

Answer failed(std::string reason) {
  return {.kind = Answer::Kind::failed, .counts = {}, .reason = std::move(reason)};
}

Answer run_once(const std::vector<std::string>& words, WorkFolder& folder, const Scene& scene,
                Deadline deadline) {
  const std::string run = std::to_string(folder.next_run());
  const fs::path scene_file = folder.path() / ("scene_" + run + ".txt");
  const fs::path counts_file = folder.path() / ("counts_" + run + ".pgm");
  write_scene_file(scene_file, scene);
  std::vector<std::string> argv;
  for (const auto& word : words) {
    argv.push_back(
        replaced(replaced(word, "{scene}", scene_file.string()), "{counts}", counts_file.string()));
  }
  ProgramRun ran;
  try {
    ran = run_program(argv, {.search_path = true, .discard_output = true, .deadline = deadline});
  } catch (const std::runtime_error& e) {
    return failed(e.what());
  }
  // The program's own words, whole up to a line's worth (a refusal says why), escaped.
  std::string said = std::move(ran.errors);
  while (!said.empty() && (said.back() == '\n' || said.back() == '\r')) said.pop_back();
  const std::string message =
      said.size() <= 400 ? printable_text(said) : printable_text(said.substr(0, 400)) + "...";
  if (ran.timed_out) return failed("did not finish in time and was killed");
  if (ran.signal != 0) {
    return failed("crashed: " + signal_name(ran.signal) +
                  (message.empty() ? "" : ", saying " + message));
  }
  const int code = ran.exit_code;
  if (code != 0) {
    if (message.empty())
      return failed("exit status " + std::to_string(code) + " without a message");
    return {.kind = Answer::Kind::refused,
            .counts = {},
            .reason = "exit status " + std::to_string(code) + ": " + message};
  }
  const std::string bytes = whole_file(counts_file);
  if (bytes.empty()) return failed("exit status 0, but no counts file was written");
  try {
    CountsImage image =
        decode_counts_pgm({reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()});
    if (image.width != scene.width || image.height != scene.height) {
      return failed("counts of " + std::to_string(image.width) + "x" +
                    std::to_string(image.height) + " pixels for a " + std::to_string(scene.width) +
                    "x" + std::to_string(scene.height) + " canvas");
    }
    return {.kind = Answer::Kind::counts, .counts = std::move(image.counts), .reason = {}};
  } catch (const std::runtime_error& e) {
    return failed(std::string("unreadable counts: ") + e.what());
  }
}

}  // namespace

std::vector<std::string> command_words(std::string_view command) {
  std::vector<std::string> words;
  std::string word;
  bool in_word = false;
  char quote = 0;
  for (const char c : command) {
    if (quote != 0) {
      if (c == quote) {
        quote = 0;
      } else {
        word += c;
      }
    } else if (c == '\'' || c == '"') {
      quote = c;
      in_word = true;
    } else if (c == ' ' || c == '\t') {
      if (in_word) words.push_back(std::move(word));
      word.clear();
      in_word = false;
    } else {
      word += c;
      in_word = true;
    }
  }
  if (quote != 0) throw UsageError("--command has an unclosed quote");
  if (in_word) words.push_back(std::move(word));
  if (words.empty()) throw UsageError("--command is empty");
  const auto names = [&words](std::string_view placeholder) {
    return std::any_of(words.begin(), words.end(), [&](const std::string& w) {
      return w.find(placeholder) != std::string::npos;
    });
  };
  if (!names("{scene}") || !names("{counts}")) {
    throw UsageError(
        "--command must name both {scene} and {counts}, the files it reads and writes");
  }
  return words;
}

GradedRasterizer graded_command(std::string_view command) {
  auto words = command_words(command);
  auto folder = std::make_shared<WorkFolder>();
  return {
      .name = std::string(command),
      .threaded = false,
      .draw = [words = std::move(words), folder](const Scene& scene, Threads, Deadline deadline) {
        return run_once(words, *folder, scene, deadline);
      }};
}

}  // namespace tri::conformance
