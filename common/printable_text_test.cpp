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

TEST_CASE(
    "A printable excerpt escapes Unicode's format characters and the line and paragraph "
    "separators",
    "[common][printable]") {
  CHECK(printable_excerpt("a\u2028b\u2029c") == "a\\xE2\\x80\\xA8b\\xE2\\x80\\xA9c");
  CHECK(printable_excerpt("\u061C\u2060\u00AD") == "\\xD8\\x9C\\xE2\\x81\\xA0\\xC2\\xAD");
  CHECK(
      printable_excerpt("\u200B\u200F\u202A\u2066\u2069\uFEFF") ==
      "\\xE2\\x80\\x8B\\xE2\\x80\\x8F\\xE2\\x80\\xAA\\xE2\\x81\\xA6\\xE2\\x81\\xA9\\xEF\\xBB\\xBF");
  // Tag characters (an invisible "hi" and the cancel tag) and an interlinear annotation anchor.
  CHECK(printable_excerpt("x\U000E0068\U000E0069\U000E007F\uFFF9") ==
        "x\\xF3\\xA0\\x81\\xA8\\xF3\\xA0\\x81\\xA9\\xF3\\xA0\\x81\\xBF\\xEF\\xBF\\xB9");
  // Visible neighbours stay: the hyphen, the en dash, the Arabic letter alef, a CJK character.
  CHECK(printable_excerpt("-\u2013\u0627\u4E2D\u2030") == "-\u2013\u0627\u4E2D\u2030");
}

TEST_CASE("A printable text escapes like an excerpt and keeps the whole text",
          "[common][printable]") {
  const std::string path = "/tmp/" + std::string(100, 'p') + "\x1b]0;x\x07\n.png";
  CHECK(printable_text(path) == "/tmp/" + std::string(100, 'p') + "\\x1B]0;x\\x07\\x0A.png");
  CHECK(printable_text("\u202Egnp.exe") == "\\xE2\\x80\\xAEgnp.exe");
  CHECK(printable_text(printable_text("\x1b\u2028")) == printable_text("\x1b\u2028"));
}

}  // namespace tri
