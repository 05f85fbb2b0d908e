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

// The next header number of a PGM after whitespace and comments; advances `at` past it.
long long pgm_header_number(std::span<const std::uint8_t> bytes, std::size_t& at) {
  while (at < bytes.size()) {
    if (bytes[at] == '#') {
      while (at < bytes.size() && bytes[at] != '\n') ++at;
    } else if (bytes[at] == ' ' || bytes[at] == '\n' || bytes[at] == '\r' || bytes[at] == '\t') {
      ++at;
    } else {
      break;
    }
  }
  long long value = 0;
  const std::size_t start = at;
  while (at < bytes.size() && bytes[at] >= '0' && bytes[at] <= '9' && at - start < 9) {
    value = value * 10 + (bytes[at++] - '0');
  }
  if (at == start) throw std::runtime_error("the PGM header lacks a number");
  return value;
}

}  // namespace

CountsImage decode_counts_pgm(std::span<const std::uint8_t> bytes) {
  if (bytes.size() < 2 || bytes[0] != 'P' || bytes[1] != '5') {
    throw std::runtime_error("not a binary PGM (it does not start with P5)");
  }
  std::size_t at = 2;
  const long long width = pgm_header_number(bytes, at);
  const long long height = pgm_header_number(bytes, at);
  const long long maxval = pgm_header_number(bytes, at);
  if (width < 1 || height < 1 || width > max_canvas_side || height > max_canvas_side) {
    throw std::runtime_error("a PGM of " + std::to_string(width) + "x" + std::to_string(height) +
                             " pixels (each side must be 1 to " + std::to_string(max_canvas_side) +
                             ")");
  }
  if (maxval < 1 || maxval > 65535) {
    throw std::runtime_error("a PGM maxval of " + std::to_string(maxval) + " (1 to 65535)");
  }
  if (at >= bytes.size()) throw std::runtime_error("the PGM ends after its header");
  ++at;  // the single whitespace character that ends the header
  const std::size_t per_pixel = maxval > 255 ? 2 : 1;
  const std::size_t expected = static_cast<std::size_t>(width * height) * per_pixel;
  if (bytes.size() - at != expected) {
    throw std::runtime_error("the PGM holds " + std::to_string(bytes.size() - at) +
                             " bytes of pixels where " + std::to_string(expected) +
                             " were expected");
  }
  CountsImage image{static_cast<int>(width), static_cast<int>(height), {}};
  image.counts.resize(static_cast<std::size_t>(width * height));
  for (int row = 0; row < image.height; ++row) {
    const int y = image.height - 1 - row;  // the file's first row is the top one
    for (int x = 0; x < image.width; ++x) {
      const std::size_t from = at + (static_cast<std::size_t>(row) * image.width + x) * per_pixel;
      const std::uint32_t value =
          per_pixel == 2 ? (std::uint32_t{bytes[from]} << 8) | bytes[from + 1] : bytes[from];
      image.counts[pixel_index(x, y, image.width)] = value;
    }
  }
  return image;
}

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
  return encode_counts_pgm(canvas.width(), canvas.height(), canvas.write_counts());
}

std::vector<std::uint8_t> encode_counts_pgm(int w, int h, std::span<const std::uint32_t> counts) {
  if (counts.size() != static_cast<std::size_t>(w) * static_cast<std::size_t>(h)) {
    throw std::logic_error("the write counts do not match a " + std::to_string(w) + "x" +
                           std::to_string(h) + " canvas");
  }
  const std::string header = "P5\n" + std::to_string(w) + " " + std::to_string(h) + "\n255\n";
  std::vector<std::uint8_t> pgm(header.begin(), header.end());
  pgm.reserve(pgm.size() + counts.size());
  for (int y = h - 1; y >= 0; --y) {
    for (int x = 0; x < w; ++x) {
      pgm.push_back(
          static_cast<std::uint8_t>(std::min<std::uint32_t>(counts[pixel_index(x, y, w)], 255)));
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
