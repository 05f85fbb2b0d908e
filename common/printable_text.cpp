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

// The code point of a valid UTF-8 sequence.
std::uint32_t code_point(std::string_view sequence) {
  const auto byte = [&](std::size_t i) {
    return static_cast<std::uint32_t>(static_cast<std::uint8_t>(sequence[i]));
  };
  if (sequence.size() == 1) return byte(0);
  const std::uint32_t lead_bits[] = {0, 0, 0x1F, 0x0F, 0x07};
  std::uint32_t code = byte(0) & lead_bits[sequence.size()];
  for (std::size_t i = 1; i < sequence.size(); ++i) code = (code << 6) | (byte(i) & 0x3F);
  return code;
}

// Characters that a terminal does not show as themselves: C0 controls, DEL, C1 controls, the
// format characters of Unicode's category Cf (soft hyphen, zero-width and bidirectional
// controls, invisible operators, the byte order mark, tags...) and the line and paragraph
// separators U+2028 and U+2029, which hide, reorder or break a message.
bool is_hidden(std::uint32_t c) {
  struct Range {
    std::uint32_t first, last;
  };
  static constexpr Range hidden[] = {
      {0x00, 0x1F},       {0x7F, 0x9F},       {0xAD, 0xAD},       {0x600, 0x605},
      {0x61C, 0x61C},     {0x6DD, 0x6DD},     {0x70F, 0x70F},     {0x890, 0x891},
      {0x8E2, 0x8E2},     {0x180E, 0x180E},   {0x200B, 0x200F},   {0x2028, 0x202E},
      {0x2060, 0x2064},   {0x2066, 0x206F},   {0xFEFF, 0xFEFF},   {0xFFF9, 0xFFFB},
      {0x110BD, 0x110BD}, {0x110CD, 0x110CD}, {0x13430, 0x1343F}, {0x1BCA0, 0x1BCA3},
      {0x1D173, 0x1D17A}, {0xE0000, 0xE007F},
  };
  for (const Range& r : hidden) {
    if (c >= r.first && c <= r.last) return true;
  }
  return false;
}

void append_escaped(std::string& out, std::uint8_t byte) {
  constexpr char digits[] = "0123456789ABCDEF";
  out += "\\x";
  out += digits[byte >> 4];
  out += digits[byte & 0xF];
}

}  // namespace

namespace {

// The text escaped, stopping after `most` characters with "...(N bytes)" when there is more.
std::string escaped(std::string_view text, std::size_t most) {
  std::string out;
  std::size_t shown = 0;
  std::size_t i = 0;
  while (i < text.size() && shown < most) {
    const std::size_t length = utf8_sequence_length(text.substr(i));
    if (length == 0 || is_hidden(code_point(text.substr(i, length)))) {
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

}  // namespace

std::string printable_excerpt(std::string_view text) {
  return escaped(text, max_excerpt_characters);
}

std::string printable_text(std::string_view text) {
  return escaped(text, text.size());
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
