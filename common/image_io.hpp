/// @file
/// Writing a canvas to disk: its colours as PNG, its write counts as binary PGM.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

#include "common/canvas.hpp"

namespace tri {

/// The canvas as PNG bytes (RGBA8), top row first so the image reads the way y-up coordinates do.
std::vector<std::uint8_t> encode_png(const Canvas& canvas);

/// The canvas's per-pixel write counts as a binary PGM ("P5", maxval 255, counts above 255
/// saturate), top row first. Throws std::logic_error when write counting is off.
std::vector<std::uint8_t> encode_counts_pgm(const Canvas& canvas);
/// The same for counts held apart from a canvas: w x h of them, bottom row first (as
/// Canvas::write_counts). Throws std::logic_error when their number is not w x h.
std::vector<std::uint8_t> encode_counts_pgm(int w, int h, std::span<const std::uint32_t> counts);

/// Write counts read back from a binary PGM, bottom row first (as Canvas::write_counts).
struct CountsImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint32_t> counts;
};

/// Reads what encode_counts_pgm writes: "P5", width, height, a maxval of at most 65535 (two bytes
/// a pixel, big-endian, above 255), '#' comments in the header, top row first. Throws
/// std::runtime_error saying what is wrong (a bad header, a side beyond max_canvas_side, a short
/// or long body).
CountsImage decode_counts_pgm(std::span<const std::uint8_t> bytes);

/// Writes bytes to a file by the promises of output_files.hpp (a unique temporary, synced, renamed
/// over the target), so a failure never leaves a half-written file behind. Creates missing parent
/// folders. Throws OutputError (a std::runtime_error) with the path and the reason on failure.
void write_file_atomically(const std::filesystem::path& path, std::span<const std::uint8_t> bytes);

/// encode_png + write_file_atomically.
void write_png(const Canvas& canvas, const std::filesystem::path& path);
/// encode_counts_pgm + write_file_atomically.
void write_counts_pgm(const Canvas& canvas, const std::filesystem::path& path);

}  // namespace tri
