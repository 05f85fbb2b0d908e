#include "tests/conventions/test_names.hpp"

#include <cctype>
#include <regex>

namespace tri::conventions {
namespace {

bool is_identifier_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
}

int line_at(std::string_view text, std::size_t offset) {
  int line = 1;
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) line += text[i] == '\n' ? 1 : 0;
  return line;
}

void skip_space(std::string_view text, std::size_t& at) {
  while (at < text.size() && std::isspace(static_cast<unsigned char>(text[at])) != 0) ++at;
}

// Reads consecutive string literals ("a" "b" -> "ab") starting at `at`, which moves past them.
std::string read_literals(std::string_view text, std::size_t& at) {
  std::string value;
  skip_space(text, at);
  while (at < text.size() && text[at] == '"') {
    for (++at; at < text.size() && text[at] != '"'; ++at) {
      if (text[at] == '\\' && at + 1 < text.size()) ++at;  // keep the escaped character
      value += text[at];
    }
    ++at;
    skip_space(text, at);
  }
  return value;
}

std::vector<std::string> split_tags(const std::string& tags) {
  std::vector<std::string> out;
  const std::regex tag(R"(\[([^\]]*)\])");
  for (auto it = std::sregex_iterator(tags.begin(), tags.end(), tag); it != std::sregex_iterator();
       ++it) {
    out.push_back((*it)[1].str());
  }
  return out;
}

// The code with string literals and comments blanked, so a word found in it is really code.
std::string code_only(std::string_view source) {
  std::string code(source);
  for (std::size_t i = 0; i < code.size(); ++i) {
    if (code[i] == '"') {
      for (++i; i < code.size() && code[i] != '"'; ++i) {
        if (code[i] == '\\') code[i++] = ' ';
        if (i < code.size() && code[i] != '\n') code[i] = ' ';
      }
    } else if (code.compare(i, 2, "//") == 0) {
      for (; i < code.size() && code[i] != '\n'; ++i) code[i] = ' ';
    }
  }
  return code;
}

// True when `word` occurs in the code as a whole identifier, or as the start of one followed by
// '_' (cairo -> cairo_fill) or as a namespace (ch04 -> ch04::).
bool names_code(std::string_view code, std::string_view word) {
  for (auto at = code.find(word); at != std::string_view::npos; at = code.find(word, at + 1)) {
    if (at > 0 && is_identifier_char(code[at - 1])) continue;
    const std::size_t end = at + word.size();
    if (end >= code.size() || !is_identifier_char(code[end]) || code[end] == '_') return true;
  }
  return false;
}

bool is_chapter_prefix(std::string_view prefix) {
  return prefix.size() > 3 && std::isdigit(static_cast<unsigned char>(prefix[0])) != 0 &&
         std::isdigit(static_cast<unsigned char>(prefix[1])) != 0 && prefix[2] == '_';
}

}  // namespace

std::vector<DeclaredTest> declared_tests(std::string_view source) {
  std::vector<DeclaredTest> tests;
  const std::string_view keyword = "TEST_CASE(";
  for (auto at = source.find(keyword); at != std::string_view::npos;
       at = source.find(keyword, at + 1)) {
    if (at > 0 && is_identifier_char(source[at - 1])) continue;  // e.g. TEMPLATE_TEST_CASE
    std::size_t cursor = at + keyword.size();
    skip_space(source, cursor);
    if (cursor >= source.size() || source[cursor] != '"') continue;  // the macro's own text
    DeclaredTest test;
    test.line = line_at(source, at);
    test.name = read_literals(source, cursor);
    if (cursor < source.size() && source[cursor] == ',') {
      ++cursor;
      test.tags = split_tags(read_literals(source, cursor));
    }
    tests.push_back(std::move(test));
  }
  return tests;
}

std::string convention_problem(const DeclaredTest& test, std::string_view prefix,
                               const std::set<int>& steps, std::string_view code) {
  if (test.name.empty()) return "the name is empty";
  if (test.name.back() == '.') return "the name ends with a full stop";
  // CTest takes a ';' in a name as a list separator: the test would split and run nothing.
  if (test.name.find(';') != std::string::npos)
    return "the name holds a ';', which splits it into two CTest tests that run nothing";
  const char first = test.name.front();
  if (std::islower(static_cast<unsigned char>(first)) != 0) {
    std::size_t end = 0;
    while (end < test.name.size() && is_identifier_char(test.name[end])) ++end;
    const std::string word = test.name.substr(0, end);
    if (!names_code(code_only(code), word)) {
      return "the name starts in lower case with \"" + word +
             "\", which is not an identifier of the test's code: start with a capital";
    }
  }
  if (test.tags.empty() || test.tags.front() != prefix) {
    return "the first tag must be [" + std::string(prefix) + "], the folder's test prefix";
  }
  if (is_chapter_prefix(prefix)) {
    if (test.tags.size() < 2)
      return "a chapter test needs a second tag: [stepN], [traps] or a topic";
    const std::string& second = test.tags[1];
    static const std::regex step(R"(step([0-9]+))");
    std::smatch match;
    if (std::regex_match(second, match, step) && steps.count(std::stoi(match[1].str())) == 0) {
      return "[" + second + "] names no \"## Step " + match[1].str() + "\" of the chapter README";
    }
  }
  return {};
}

std::set<int> step_numbers(std::string_view readme) {
  std::set<int> steps;
  const std::string text(readme);
  static const std::regex heading(R"((^|\n)## Step ([0-9]+))");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), heading);
       it != std::sregex_iterator(); ++it) {
    steps.insert(std::stoi((*it)[2].str()));
  }
  return steps;
}

std::map<std::string, int> quoted_test_names(std::string_view readme) {
  std::map<std::string, int> names;
  const std::string_view markers[] = {"Test: ", "Tests: "};
  for (const std::string_view marker : markers) {
    for (auto at = readme.find(marker); at != std::string_view::npos;
         at = readme.find(marker, at + 1)) {
      std::size_t cursor = at + marker.size();
      // The quotes that follow, separated by ", " (or " and "), up to the end of the list.
      while (cursor < readme.size() && readme[cursor] == '"') {
        const std::size_t close = readme.find('"', cursor + 1);
        if (close == std::string_view::npos) break;
        std::string name;
        for (std::size_t i = cursor + 1; i < close; ++i) {
          const bool space = std::isspace(static_cast<unsigned char>(readme[i])) != 0;
          if (space && (name.empty() || name.back() == ' ')) continue;
          name += space ? ' ' : readme[i];
        }
        while (!name.empty() && name.back() == ' ') name.pop_back();
        names.emplace(name, line_at(readme, cursor));
        cursor = close + 1;
        for (const std::string_view joint : {", and ", ", ", " and ", ",\n", " and\n"}) {
          if (readme.substr(cursor, joint.size()) == joint) {
            cursor += joint.size();
            skip_space(readme, cursor);
            break;
          }
        }
      }
    }
  }
  return names;
}

}  // namespace tri::conventions
