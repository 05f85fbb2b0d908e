#include "common/temporary_folder.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

namespace tri {

namespace fs = std::filesystem;

TEST_CASE("A temporary folder is new and empty, named by its prefix, and goes with its contents",
          "[common][temporary_folder]") {
  fs::path kept;
  {
    const TemporaryFolder first("tri_temporary_folder_test");
    const TemporaryFolder second("tri_temporary_folder_test");
    CHECK(first.path() != second.path());
    CHECK(fs::equivalent(first.path().parent_path(), fs::temp_directory_path()));
    CHECK(first.path().filename().string().starts_with("tri_temporary_folder_test_"));
    REQUIRE(fs::is_directory(first.path()));
    CHECK(fs::is_empty(first.path()));
    CHECK(first / "a.txt" == first.path() / "a.txt");
    fs::create_directories(first / "inner" / "deeper");
    std::ofstream(first / "inner" / "deeper" / "file.txt") << "text";
    kept = first.path();
  }
  CHECK_FALSE(fs::exists(kept));
}

TEST_CASE("whole_file gives every byte of a file, and nothing for a file it cannot read",
          "[common][temporary_folder]") {
  const TemporaryFolder folder("tri_whole_file_test");
  const std::string bytes("line\r\n\0\xff end", 12);
  std::ofstream(folder / "bytes", std::ios::binary) << bytes;
  CHECK(whole_file(folder / "bytes") == bytes);
  CHECK(whole_file(folder / "missing").empty());
}

}  // namespace tri
