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

/// Writes bytes to a file by the promises of output_files.hpp (a unique temporary, synced, renamed
/// over the target), so a failure never leaves a half-written file behind. Creates missing parent
/// folders. Throws OutputError (a std::runtime_error) with the path and the reason on failure.
void write_file_atomically(const std::filesystem::path& path, std::span<const std::uint8_t> bytes);

/// encode_png + write_file_atomically.
void write_png(const Canvas& canvas, const std::filesystem::path& path);
/// encode_counts_pgm + write_file_atomically.
void write_counts_pgm(const Canvas& canvas, const std::filesystem::path& path);

}  // namespace tri
