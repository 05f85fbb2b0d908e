/// @file
/// Scenes: a canvas size and an ordered list of coloured triangles and lines, read from a small
/// text format (@ref design_scenes "docs/DESIGN.md section 4").
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <istream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <glm/vec2.hpp>

#include "common/color.hpp"

namespace tri {

/// Coordinates must lie within ±2^30 pixels: far enough to test huge triangles, small enough that
/// fixed-point rasterizers can reason about their bit budgets.
inline constexpr double max_scene_coordinate = 1073741824.0;

/// The longest scene line, in bytes (without its end of line): a longer line is an error, so a
/// stream without line breaks (/dev/zero, a corrupt file) is refused after reading this much.
inline constexpr std::size_t max_scene_line_bytes = 64 * 1024;

/// The most primitives (triangles and lines) a scene may have, far more than any scene of the
/// book; more is an error rather than an exhausted machine. Reading that many peaks at 128 MiB
/// (64 bytes a primitive, and the vector's last growth copying the first 64 MiB), as the test
/// "raster/A scene of 2,000,000 primitives takes at most 136 MiB to read and to draw on a small
/// canvas" measures.
inline constexpr std::size_t max_scene_primitives = 2'000'000;

/// The limits a parse enforces; the defaults are the documented ones (tests use smaller ones).
struct SceneLimits {
  std::size_t max_line_bytes = max_scene_line_bytes;
  std::size_t max_primitives = max_scene_primitives;
};

/// A UTF-8 byte order mark, accepted (and skipped) at the start of a scene.
inline constexpr std::string_view utf8_byte_order_mark = "\xEF\xBB\xBF";

/// A filled triangle of a scene; vertices in canvas pixel units (integers are pixel centres).
struct SceneTriangle {
  std::array<glm::dvec2, 3> vertices;
  Color color = colors::white;
};

/// A line segment of a scene.
struct SceneLine {
  std::array<glm::dvec2, 2> ends;
  Color color = colors::white;
};

/// One drawable item; the scene keeps them in file order because later ones paint over earlier.
using ScenePrimitive = std::variant<SceneTriangle, SceneLine>;

/// Everything a picture needs, and nothing more.
struct Scene {
  int width = 0;
  int height = 0;
  Color background = colors::black;
  std::vector<ScenePrimitive> primitives;
};

/// A scene that could not be read. what() is one line: "source:line: problem".
class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Hears how many bytes of the scene were read so far, about every scene_progress_bytes.
using SceneReadProgress = std::function<void(std::uint64_t bytes_read)>;

/// How many bytes a parse reads between two calls of its SceneReadProgress.
inline constexpr std::uint64_t scene_progress_bytes = std::uint64_t{1} << 20;

/// Parses the text format:
///   canvas W H [r g b]              (first directive, exactly once; 1 <= W, H <= 16384)
///   tri x0 y0 x1 y1 x2 y2 [r g b]   (decimal coordinates within ±2^30)
///   line x0 y0 x1 y1 [r g b]
/// '#' starts a comment; a UTF-8 byte order mark may start the scene. Throws SceneError naming
/// source_name and the line on the first problem, so no scene is ever returned half-read; lines
/// longer than max_scene_line_bytes and scenes of more than max_scene_primitives are problems.
/// Words of the scene appear in messages through printable_excerpt (short, escaped). Running out of
/// memory is a SceneError naming how many primitives were read and the limit to lower.
Scene parse_scene(std::istream& in, std::string_view source_name, const SceneLimits& limits = {},
                  const SceneReadProgress& on_progress = {});

/// Reads and parses a scene file (errors name the file, escaped, and the system's reason).
Scene load_scene(const std::filesystem::path& path, const SceneReadProgress& on_progress = {});

}  // namespace tri
