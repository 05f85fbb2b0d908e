#include "common/image_io.hpp"

#include <stb_image_write.h>

#include <algorithm>
#include <stdexcept>
#include <string>

#include "common/output_files.hpp"

namespace tri {
namespace {

// stb calls this with successive chunks of the encoded file.
void append_bytes(void* context, void* data, int size) {
  auto* out = static_cast<std::vector<std::uint8_t>*>(context);
  const auto* bytes = static_cast<const std::uint8_t*>(data);
  out->insert(out->end(), bytes, bytes + size);
}

}  // namespace

std::vector<std::uint8_t> encode_png(const Canvas& canvas) {
  const int w = canvas.width();
  const int h = canvas.height();
  // The canvas stores the bottom row first; image files start with the top row.
  std::vector<std::uint8_t> top_down(static_cast<std::size_t>(w) * h * 4);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const Color c = canvas.pixel(x, y);
      std::uint8_t* out = &top_down[(static_cast<std::size_t>(h - 1 - y) * w + x) * 4];
      out[0] = c.r;
      out[1] = c.g;
      out[2] = c.b;
      out[3] = c.a;
    }
  }
  std::vector<std::uint8_t> png;
  if (stbi_write_png_to_func(append_bytes, &png, w, h, 4, top_down.data(), w * 4) == 0) {
    throw std::runtime_error("PNG encoding failed");
  }
  return png;
}

std::vector<std::uint8_t> encode_counts_pgm(const Canvas& canvas) {
  if (!canvas.write_counts_enabled()) {
    throw std::logic_error("write counts were not enabled on this canvas");
  }
  const int w = canvas.width();
  const int h = canvas.height();
  const std::string header = "P5\n" + std::to_string(w) + " " + std::to_string(h) + "\n255\n";
  std::vector<std::uint8_t> pgm(header.begin(), header.end());
  pgm.reserve(pgm.size() + static_cast<std::size_t>(w) * h);
  for (int y = h - 1; y >= 0; --y) {
    for (int x = 0; x < w; ++x) {
      pgm.push_back(
          static_cast<std::uint8_t>(std::min<std::uint32_t>(canvas.write_count(x, y), 255)));
    }
  }
  return pgm;
}

void write_file_atomically(const std::filesystem::path& path, std::span<const std::uint8_t> bytes) {
  write_file_safely(path, bytes);
}

void write_png(const Canvas& canvas, const std::filesystem::path& path) {
  write_file_atomically(path, encode_png(canvas));
}

void write_counts_pgm(const Canvas& canvas, const std::filesystem::path& path) {
  write_file_atomically(path, encode_counts_pgm(canvas));
}

}  // namespace tri
