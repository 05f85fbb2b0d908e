#include "tests/support/scratch_folder.hpp"

#include <stdlib.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace tri::testing {

namespace fs = std::filesystem;

ScratchFolder::ScratchFolder(const std::string& name) {
  std::string safe = name;
  std::replace_if(
      safe.begin(), safe.end(), [](unsigned char c) { return std::isalnum(c) == 0 && c != '_'; },
      '_');
  const std::string pattern = (fs::temp_directory_path() / ("tri_" + safe + "_XXXXXX")).string();
  std::vector<char> text(pattern.begin(), pattern.end());
  text.push_back('\0');
  if (::mkdtemp(text.data()) == nullptr) {
    throw std::runtime_error("cannot create a scratch folder " + pattern + ": " +
                             std::strerror(errno));
  }
  path_ = text.data();
}

ScratchFolder::~ScratchFolder() {
  std::error_code ignored;
  fs::remove_all(path_, ignored);
}

}  // namespace tri::testing
