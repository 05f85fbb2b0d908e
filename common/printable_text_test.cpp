#include "common/printable_text.hpp"

#include <catch2/catch.hpp>

#include <string>

namespace tri {

TEST_CASE("A printable excerpt keeps plain text and valid UTF-8 as it is", "[common][printable]") {
  CHECK(printable_excerpt("canvas") == "canvas");
  CHECK(printable_excerpt("") == "");
  CHECK(printable_excerpt("ü½€𝄞") == "ü½€𝄞");
}

TEST_CASE("A printable excerpt escapes control characters, NUL and terminal escapes",
          "[common][printable]") {
  CHECK(printable_excerpt(std::string("a\0b", 3)) == "a\\x00b");
  CHECK(printable_excerpt("\x1b[31mred") == "\\x1B[31mred");
  CHECK(printable_excerpt("tab\there\r\n") == "tab\\x09here\\x0D\\x0A");
  CHECK(printable_excerpt("\x7f") == "\\x7F");
  CHECK(printable_excerpt("\xc2\x9b"
                          "2J") == "\\xC2\\x9B2J");  // C1 CSI
}

TEST_CASE("A printable excerpt escapes invalid UTF-8 byte by byte and invisible characters",
          "[common][printable]") {
  CHECK(printable_excerpt("\xff\xfe") == "\\xFF\\xFE");
  CHECK(printable_excerpt("\xc3") == "\\xC3");                    // cut sequence
  CHECK(printable_excerpt("\xc0\xaf") == "\\xC0\\xAF");           // overlong '/'
  CHECK(printable_excerpt("\xed\xa0\x80") == "\\xED\\xA0\\x80");  // surrogate
  CHECK(printable_excerpt("\xef\xbb\xbf"
                          "canvas") == "\\xEF\\xBB\\xBFcanvas");  // BOM
  CHECK(printable_excerpt("a\xe2\x80\xae"
                          "b") == "a\\xE2\\x80\\xAEb");  // right-to-left override
}

TEST_CASE("A printable excerpt shows at most 32 characters and says how long the text was",
          "[common][printable]") {
  const std::string long_word(10'000'000, 'x');
  CHECK(printable_excerpt(long_word) == std::string(32, 'x') + "...(10000000 bytes)");
  CHECK(printable_excerpt(std::string(32, 'y')) == std::string(32, 'y'));
  const std::string zeros(100, '\0');
  CHECK(printable_excerpt(zeros).size() == 32 * 4 + std::string("...(100 bytes)").size());
}

}  // namespace tri
