/// @file
/// Showing untrusted text (a word from a scene file, a name from the command line) in a message:
/// short, on one line, and harmless to a terminal; and any text inside an XML (SVG) document.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace tri {

/// How many characters of an untrusted word a message shows at most.
inline constexpr std::size_t max_excerpt_characters = 32;

/// The text with control characters (C0, DEL, C1), Unicode's format characters (category Cf:
/// soft hyphen, zero-width and bidirectional controls, byte order mark, tags...), the line and
/// paragraph separators U+2028 and U+2029, and bytes that are not valid UTF-8 written as `\xNN`
/// (each byte of the character), other UTF-8 kept; cut after max_excerpt_characters with
/// "...(N bytes)" saying how long it was.
std::string printable_excerpt(std::string_view text);

/// The same escaping without the cut, for a path or a message that must be shown whole: one line
/// of text that a terminal shows as it is.
std::string printable_text(std::string_view text);

/// Text with &, <, > and " replaced by their XML entities, for an SVG's text and attributes.
std::string escape_xml(std::string_view text);

}  // namespace tri
