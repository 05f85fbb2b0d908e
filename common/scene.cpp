#include "common/scene.hpp"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <locale>
#include <new>
#include <sstream>

#include "common/canvas.hpp"
#include "common/printable_text.hpp"

namespace tri {
namespace {

std::vector<std::string_view> split_words(std::string_view line) {
  std::vector<std::string_view> words;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    std::size_t end = i;
    while (end < line.size() && line[end] != ' ' && line[end] != '\t' && line[end] != '\r') ++end;
    if (end > i) words.push_back(line.substr(i, end - i));
    i = end;
  }
  return words;
}

// The value of a well-formed number that from_chars found out of range: ±max when it is too large
// for a double (so the caller reports it beyond ±2^30), else the nearest double, 0 or a subnormal.
double magnitude_beyond_double(std::string_view word) {
  std::istringstream in{std::string(word)};
  in.imbue(std::locale::classic());
  double value = 0.0;
  in >> value;  // overflow gives ±max or ±inf depending on the library, underflow about 0
  if (std::abs(value) >= 1.0) return std::copysign(std::numeric_limits<double>::max(), value);
  return value;
}

// Reads one directive's words, throwing SceneError with the position on the first problem.
class LineReader {
 public:
  LineReader(std::string_view source, std::uint64_t line_number)
      : source_(source), line_(line_number) {}

  [[noreturn]] void fail(const std::string& problem) const {
    throw SceneError(printable_text(source_) + ":" + std::to_string(line_) + ": " + problem);
  }

  double coordinate(std::string_view word, std::string_view what) const {
    double value = 0.0;
    const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
    const bool whole_word = end == word.data() + word.size();
    if (error == std::errc::result_out_of_range && whole_word) {
      // from_chars reports 1e-400 (too close to zero for a double) like 1e400 (too large).
      value = magnitude_beyond_double(word);
    } else if (error != std::errc() || !whole_word) {
      fail("expected a decimal number for " + std::string(what) + ", got '" +
           printable_excerpt(word) + "'");
    }
    if (std::isnan(value)) fail(std::string(what) + " is NaN; coordinates must be finite numbers");
    if (std::isinf(value)) {
      fail(std::string(what) + " is infinite; coordinates must be finite numbers");
    }
    if (std::abs(value) > max_scene_coordinate) {
      fail(std::string(what) + " " + printable_excerpt(word) + " is outside ±2^30 (1073741824)");
    }
    return value;
  }

  int integer(std::string_view word, std::string_view what, int low, int high) const {
    int value = 0;
    const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
    const bool whole_word = end == word.data() + word.size();
    if (error == std::errc::result_out_of_range && whole_word) {
      fail(std::string(what) + " " + printable_excerpt(word) + " is outside " +
           std::to_string(low) + ".." + std::to_string(high));
    }
    if (error != std::errc() || !whole_word) {
      fail("expected a whole number for " + std::string(what) + ", got '" +
           printable_excerpt(word) + "'");
    }
    if (value < low || value > high) {
      fail(std::string(what) + " " + std::to_string(value) + " is outside " + std::to_string(low) +
           ".." + std::to_string(high));
    }
    return value;
  }

  // Reads an optional "r g b" at words[first..]; `absent` when the line has none.
  Color color(const std::vector<std::string_view>& words, std::size_t first, Color absent) const {
    if (words.size() == first) return absent;
    const auto channel = [&](std::size_t i, const char* name) {
      return static_cast<std::uint8_t>(integer(words[first + i], name, 0, 255));
    };
    return Color{channel(0, "red"), channel(1, "green"), channel(2, "blue"), 255};
  }

  void expect_count(const std::vector<std::string_view>& words, std::size_t bare,
                    const char* usage) const {
    if (words.size() != bare && words.size() != bare + 3) {
      const std::size_t count = words.size() - 1;
      fail(std::string("expected '") + usage + "', got " + std::to_string(count) +
           (count == 1 ? " value" : " values"));
    }
  }

 private:
  std::string_view source_;
  std::uint64_t line_;
};

enum class LineStatus { line, too_long, end };

// Reads one line into buffer (sized max_line_bytes + 1) without ever holding more than that: a
// longer line is reported as soon as its first max_line_bytes bytes are read. Adds the bytes it
// read to bytes_read.
LineStatus read_line(std::istream& in, std::string& buffer, std::string_view& line,
                     std::uint64_t& bytes_read) {
  errno = 0;
  in.getline(buffer.data(), static_cast<std::streamsize>(buffer.size()));
  const auto count = static_cast<std::size_t>(in.gcount());
  bytes_read += count;
  if (in.bad()) return LineStatus::end;
  if (in.fail()) {
    if (in.eof() && count == 0) return LineStatus::end;
    return LineStatus::too_long;  // the buffer filled before the end of the line
  }
  line = std::string_view(buffer.data(), in.eof() ? count : count - 1);  // without the '\n'
  return LineStatus::line;
}

glm::dvec2 point(const LineReader& reader, const std::vector<std::string_view>& words,
                 std::size_t first, std::size_t index) {
  const std::string x = "x" + std::to_string(index);
  const std::string y = "y" + std::to_string(index);
  return {reader.coordinate(words[first], x), reader.coordinate(words[first + 1], y)};
}

// A triangle or a line from its directive's words: its n points (x0 y0 x1 y1 ...) into the
// member `points`, then an optional colour (white when absent). `usage` is the directive's form,
// for the message when the count of values is wrong.
template <class Primitive, std::size_t n>
Primitive read_primitive(const LineReader& reader, const std::vector<std::string_view>& words,
                         const char* usage, std::array<glm::dvec2, n> Primitive::*points) {
  reader.expect_count(words, 1 + 2 * n, usage);
  Primitive primitive;
  for (std::size_t i = 0; i < n; ++i) (primitive.*points)[i] = point(reader, words, 1 + 2 * i, i);
  primitive.color = reader.color(words, 1 + 2 * n, colors::white);
  return primitive;
}

}  // namespace

Scene parse_scene(std::istream& in, std::string_view source_name, const SceneLimits& limits,
                  const SceneReadProgress& on_progress) {
  Scene scene;
  bool have_canvas = false;
  std::string buffer(limits.max_line_bytes + 1, '\0');
  std::uint64_t line_number = 0;
  std::uint64_t bytes_read = 0;
  std::uint64_t next_report = scene_progress_bytes;
  std::string_view line;
  while (true) {
    const LineStatus status = read_line(in, buffer, line, bytes_read);
    if (status == LineStatus::end) break;
    ++line_number;
    if (bytes_read >= next_report && on_progress) {
      on_progress(bytes_read);
      next_report = bytes_read + scene_progress_bytes;
    }
    if (status == LineStatus::too_long) {
      LineReader(source_name, line_number)
          .fail("line longer than " + std::to_string(limits.max_line_bytes) +
                " bytes, the limit of a scene line");
    }
    if (line_number == 1 && line.starts_with(utf8_byte_order_mark)) {
      line.remove_prefix(utf8_byte_order_mark.size());
    }
    if (const auto hash = line.find('#'); hash != std::string_view::npos)
      line = line.substr(0, hash);
    const auto words = split_words(line);
    if (words.empty()) continue;
    const LineReader reader(source_name, line_number);
    const std::string_view directive = words[0];
    if (directive == "canvas") {
      if (have_canvas) reader.fail("a scene has exactly one 'canvas' directive");
      reader.expect_count(words, 3, "canvas W H [r g b]");
      scene.width = reader.integer(words[1], "canvas width", 1, max_canvas_side);
      scene.height = reader.integer(words[2], "canvas height", 1, max_canvas_side);
      scene.background = reader.color(words, 3, colors::black);
      have_canvas = true;
    } else if (directive == "tri" || directive == "line") {
      if (!have_canvas)
        reader.fail("'" + std::string(directive) + "' before the 'canvas' directive");
      if (scene.primitives.size() == limits.max_primitives) {
        reader.fail("more than " + std::to_string(limits.max_primitives) +
                    " primitives, the limit of a scene");
      }
      const ScenePrimitive primitive =
          directive == "tri"
              ? ScenePrimitive(read_primitive(reader, words, "tri x0 y0 x1 y1 x2 y2 [r g b]",
                                              &SceneTriangle::vertices))
              : ScenePrimitive(
                    read_primitive(reader, words, "line x0 y0 x1 y1 [r g b]", &SceneLine::ends));
      try {
        scene.primitives.push_back(primitive);
      } catch (const std::bad_alloc&) {
        reader.fail("out of memory while storing the scene's primitives (" +
                    std::to_string(scene.primitives.size()) + " read, " +
                    std::to_string(scene.primitives.capacity() * sizeof(ScenePrimitive) >> 20) +
                    " MiB held); lower the number of triangles and lines");
      }
    } else {
      reader.fail("unknown directive '" + printable_excerpt(directive) +
                  "' (expected canvas, tri or line)");
    }
  }
  if (in.bad()) {
    const int error = errno;
    throw SceneError(printable_text(source_name) + ": read error" +
                     (error != 0 ? std::string(": ") + std::strerror(error) : std::string()));
  }
  if (!have_canvas) {
    throw SceneError(printable_text(source_name) + ": missing 'canvas W H' directive");
  }
  return scene;
}

Scene load_scene(const std::filesystem::path& path, const SceneReadProgress& on_progress) {
  // A folder opens as a stream on Linux and fails only when read: name the reason up front.
  std::error_code ignored;
  if (std::filesystem::is_directory(path, ignored)) {
    throw SceneError(printable_text(path.string()) +
                     ": cannot read the scene file: " + std::strerror(EISDIR));
  }
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    const int error = errno;
    throw SceneError(printable_text(path.string()) + ": cannot open the scene file" +
                     (error != 0 ? std::string(": ") + std::strerror(error) : std::string()));
  }
  return parse_scene(in, path.string(), {}, on_progress);
}

}  // namespace tri
