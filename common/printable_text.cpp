#include "common/printable_text.hpp"

#include <cstdint>

namespace tri {
namespace {

// The length of the valid UTF-8 sequence at the start of text, or 0 when it is not one.
std::size_t utf8_sequence_length(std::string_view text) {
  const auto byte = [&](std::size_t i) { return static_cast<std::uint8_t>(text[i]); };
  const std::uint8_t lead = byte(0);
  if (lead < 0x80) return 1;
  std::size_t length = 0;
  std::uint8_t low = 0x80, high = 0xBF;  // the range of the second byte
  if (lead >= 0xC2 && lead <= 0xDF) {
    length = 2;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    length = 3;
    if (lead == 0xE0) low = 0xA0;   // no overlong forms
    if (lead == 0xED) high = 0x9F;  // no surrogates
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    length = 4;
    if (lead == 0xF0) low = 0x90;
    if (lead == 0xF4) high = 0x8F;  // nothing above U+10FFFF
  } else {
    return 0;
  }
  if (text.size() < length || byte(1) < low || byte(1) > high) return 0;
  for (std::size_t i = 2; i < length; ++i) {
    if (byte(i) < 0x80 || byte(i) > 0xBF) return 0;
  }
  return length;
}

// Invisible or reordering characters that would hide part of a message: zero-width spaces and
// marks, bidirectional overrides and isolates, the byte order mark.
bool is_invisible(std::string_view sequence) {
  if (sequence.size() != 3) return false;
  const auto byte = [&](std::size_t i) {
    return static_cast<std::uint32_t>(static_cast<std::uint8_t>(sequence[i]));
  };
  const std::uint32_t code = ((byte(0) & 0x0F) << 12) | ((byte(1) & 0x3F) << 6) | (byte(2) & 0x3F);
  return (code >= 0x200B && code <= 0x200F) || (code >= 0x202A && code <= 0x202E) ||
         (code >= 0x2066 && code <= 0x2069) || code == 0xFEFF;
}

void append_escaped(std::string& out, std::uint8_t byte) {
  constexpr char digits[] = "0123456789ABCDEF";
  out += "\\x";
  out += digits[byte >> 4];
  out += digits[byte & 0xF];
}

}  // namespace

std::string printable_excerpt(std::string_view text) {
  std::string out;
  std::size_t shown = 0;
  std::size_t i = 0;
  while (i < text.size() && shown < max_excerpt_characters) {
    const std::size_t length = utf8_sequence_length(text.substr(i));
    const auto lead = static_cast<std::uint8_t>(text[i]);
    // C1 controls (U+0080..U+009F, encoded C2 80..C2 9F) act as terminal escapes too.
    const bool c1_control =
        length == 2 && lead == 0xC2 && static_cast<std::uint8_t>(text[i + 1]) < 0xA0;
    if (length == 0 || lead < 0x20 || lead == 0x7F || c1_control ||
        is_invisible(text.substr(i, length))) {
      const std::size_t bytes = length == 0 ? 1 : length;
      for (std::size_t b = 0; b < bytes; ++b)
        append_escaped(out, static_cast<std::uint8_t>(text[i + b]));
      i += bytes;
    } else {
      out.append(text.substr(i, length));
      i += length;
    }
    ++shown;
  }
  if (i < text.size()) out += "...(" + std::to_string(text.size()) + " bytes)";
  return out;
}

std::string escape_xml(std::string_view text) {
  std::string escaped;
  for (const char c : text) {
    switch (c) {
      case '&':
        escaped += "&amp;";
        break;
      case '<':
        escaped += "&lt;";
        break;
      case '>':
        escaped += "&gt;";
        break;
      case '"':
        escaped += "&quot;";
        break;
      default:
        escaped += c;
    }
  }
  return escaped;
}

}  // namespace tri
