#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

// stb_image decodes the PNGs back; Debian's libstb (which the common library links) contains it.
#if __has_include(<stb_image.h>)
#include <stb_image.h>
#else
#include <stb/stb_image.h>
#endif

#include "common/canvas.hpp"
#include "common/image_io.hpp"
#include "common/random.hpp"
#include "tests/support/scratch_folder.hpp"

namespace tri {
namespace {

namespace fs = std::filesystem;

std::vector<std::uint8_t> bytes_of(const std::string& text) {
  return std::vector<std::uint8_t>(text.begin(), text.end());
}

std::vector<std::uint8_t> read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::vector<std::uint8_t>(std::istreambuf_iterator<char>(in), {});
}

std::uint32_t big_endian_u32(const std::vector<std::uint8_t>& bytes, std::size_t at) {
  return (std::uint32_t{bytes.at(at)} << 24) | (std::uint32_t{bytes.at(at + 1)} << 16) |
         (std::uint32_t{bytes.at(at + 2)} << 8) | std::uint32_t{bytes.at(at + 3)};
}

// Every file below the folder (recursively), as paths relative to it, so leftovers show up.
std::vector<std::string> files_below(const fs::path& folder) {
  std::vector<std::string> names;
  for (const auto& entry : fs::recursive_directory_iterator(folder)) {
    names.push_back(fs::relative(entry.path(), folder).generic_string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

// A 5x3 canvas whose every pixel has a different colour, so a flip or a shift shows.
Canvas numbered_canvas() {
  Canvas canvas(5, 3);
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 5; ++x) {
      const auto v = static_cast<std::uint8_t>(10 * y + x);
      canvas.put_pixel(
          x, y,
          Color{v, static_cast<std::uint8_t>(100 + v), static_cast<std::uint8_t>(200 + v / 2),
                static_cast<std::uint8_t>(255 - 3 * v)});
    }
  }
  return canvas;
}

// A PNG as stb_image decodes it to RGBA8, top row first (decoded: false when stb refuses it).
struct DecodedPng {
  bool decoded = false;
  int width = 0;
  int height = 0;
  int channels = 0;  ///< in the file
  std::vector<std::uint8_t> rgba;
};

DecodedPng decode_png(const std::vector<std::uint8_t>& png) {
  DecodedPng out;
  stbi_uc* pixels = stbi_load_from_memory(png.data(), static_cast<int>(png.size()), &out.width,
                                          &out.height, &out.channels, 4);
  if (pixels == nullptr) return out;
  out.decoded = true;
  out.rgba.assign(pixels, pixels + static_cast<std::size_t>(out.width) *
                                       static_cast<std::size_t>(out.height) * 4);
  stbi_image_free(pixels);
  return out;
}

// CRC-32 of PNG chunks (ISO 3309, as the PNG specification gives it), bit by bit: a check of the
// container that shares no code with the encoder or with stb_image.
std::uint32_t png_crc(const std::vector<std::uint8_t>& bytes, std::size_t from, std::size_t to) {
  std::uint32_t crc = 0xFFFFFFFFu;
  for (std::size_t i = from; i < to; ++i) {
    crc ^= bytes[i];
    for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return crc ^ 0xFFFFFFFFu;
}

// The PNG's chunk types in order, or an empty list when a chunk's length or CRC is wrong.
std::vector<std::string> checked_chunks(const std::vector<std::uint8_t>& png) {
  std::vector<std::string> types;
  std::size_t at = 8;  // after the signature
  while (at + 12 <= png.size()) {
    const std::size_t length = big_endian_u32(png, at);
    if (at + 12 + length > png.size()) return {};
    if (png_crc(png, at + 4, at + 8 + length) != big_endian_u32(png, at + 8 + length)) return {};
    types.emplace_back(png.begin() + static_cast<std::ptrdiff_t>(at + 4),
                       png.begin() + static_cast<std::ptrdiff_t>(at + 8));
    at += 12 + length;
  }
  return at == png.size() ? types : std::vector<std::string>{};
}
}  // namespace

TEST_CASE("The counts PGM has a P5 header and lists the top row first", "[common][image_io]") {
  Canvas canvas(3, 2);
  canvas.enable_write_counts();
  canvas.put_pixel(0, 0, colors::white);
  canvas.put_pixel(2, 0, colors::white);
  canvas.put_pixel(2, 0, colors::white);
  for (int i = 0; i < 3; ++i) canvas.put_pixel(1, 1, colors::white);

  std::vector<std::uint8_t> expected = bytes_of("P5\n3 2\n255\n");
  for (const std::uint8_t count : {0, 3, 0,   // top row (y = 1)
                                   1, 0, 2})  // bottom row (y = 0)
    expected.push_back(count);
  CHECK(encode_counts_pgm(canvas) == expected);
}

TEST_CASE("The counts PGM saturates counts above 255", "[common][image_io]") {
  Canvas canvas(3, 1);
  canvas.enable_write_counts();
  for (int i = 0; i < 254; ++i) canvas.put_pixel(0, 0, colors::white);
  for (int i = 0; i < 255; ++i) canvas.put_pixel(1, 0, colors::white);
  for (int i = 0; i < 300; ++i) canvas.put_pixel(2, 0, colors::white);
  REQUIRE(canvas.write_count(2, 0) == 300);

  std::vector<std::uint8_t> expected = bytes_of("P5\n3 1\n255\n");
  expected.insert(expected.end(), {254, 255, 255});
  CHECK(encode_counts_pgm(canvas) == expected);
}

TEST_CASE("The counts PGM needs write counting to be on", "[common][image_io]") {
  const Canvas canvas(2, 2);
  CHECK_THROWS_AS(encode_counts_pgm(canvas), std::logic_error);
}

TEST_CASE("decode_counts_pgm reads back what encode_counts_pgm wrote, bottom row first",
          "[common][image_io]") {
  Canvas canvas(3, 2);
  canvas.enable_write_counts();
  canvas.put_pixel(0, 0, colors::white);
  canvas.put_pixel(2, 1, colors::white);
  canvas.put_pixel(2, 1, colors::white);
  const CountsImage image = decode_counts_pgm(encode_counts_pgm(canvas));
  CHECK(image.width == 3);
  CHECK(image.height == 2);
  const auto counts = canvas.write_counts();
  CHECK(image.counts == std::vector<std::uint32_t>(counts.begin(), counts.end()));
}

TEST_CASE("decode_counts_pgm reads comments and two-byte counts, and refuses a short body",
          "[common][image_io]") {
  std::vector<std::uint8_t> pgm = bytes_of("P5\n# a comment\n2 1\n65535\n");
  pgm.insert(pgm.end(), {0x01, 0x02, 0x00, 0x07});
  const CountsImage image = decode_counts_pgm(pgm);
  CHECK(image.counts == std::vector<std::uint32_t>{258, 7});
  pgm.pop_back();
  CHECK_THROWS_WITH(decode_counts_pgm(pgm), Catch::Contains("3 bytes of pixels where 4"));
  CHECK_THROWS_WITH(decode_counts_pgm(bytes_of("P6\n1 1\n255\n\x01")), Catch::Contains("P5"));
  CHECK_THROWS_WITH(decode_counts_pgm(bytes_of("P5\n0 1\n255\n")), Catch::Contains("0x1"));
}

TEST_CASE("The PNG has the PNG signature and an 8-bit RGBA header of the canvas size",
          "[common][image_io][png]") {
  const auto png = encode_png(numbered_canvas());
  const std::vector<std::uint8_t> signature = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  REQUIRE(png.size() > 33);
  CHECK(std::vector<std::uint8_t>(png.begin(), png.begin() + 8) == signature);
  // The first chunk is IHDR: length 13, then width, height, bit depth, colour type.
  CHECK(big_endian_u32(png, 8) == 13);
  CHECK(std::string(png.begin() + 12, png.begin() + 16) == "IHDR");
  CHECK(big_endian_u32(png, 16) == 5);
  CHECK(big_endian_u32(png, 20) == 3);
  CHECK(int{png[24]} == 8);  // bits per channel
  CHECK(int{png[25]} == 6);  // colour type 6: RGBA
  CHECK(std::string(png.end() - 8, png.end() - 4) == "IEND");
}

TEST_CASE("The PNG decodes back to the canvas, top row first, alpha included",
          "[common][image_io][png]") {
  const Canvas canvas = numbered_canvas();
  const DecodedPng png = decode_png(encode_png(canvas));
  REQUIRE(png.decoded);
  CHECK(png.width == 5);
  CHECK(png.height == 3);
  CHECK(png.channels == 4);

  std::vector<std::uint8_t> expected;
  for (int y = 2; y >= 0; --y) {
    for (int x = 0; x < 5; ++x) {
      const Color c = canvas.pixel(x, y);
      expected.insert(expected.end(), {c.r, c.g, c.b, c.a});
    }
  }
  CHECK(png.rgba == expected);
}

TEST_CASE("A one-pixel canvas encodes as a valid PNG", "[common][image_io][png]") {
  const DecodedPng png = decode_png(encode_png(Canvas(1, 1, Color{1, 2, 3, 4})));
  REQUIRE(png.decoded);
  CHECK(png.width == 1);
  CHECK(png.height == 1);
  CHECK(png.rgba == std::vector<std::uint8_t>{1, 2, 3, 4});
}

TEST_CASE("write_file_atomically creates the missing folders and leaves only the file",
          "[common][image_io][files]") {
  const testing::ScratchFolder scratch("creates_folders");
  const fs::path& folder = scratch.path();
  const fs::path path = folder / "a" / "b" / "figure.bin";
  const std::vector<std::uint8_t> bytes = {0, 1, 2, 255, '\n', '\r', 0};
  write_file_atomically(path, bytes);
  CHECK(read_file(path) == bytes);
  CHECK(files_below(folder) == std::vector<std::string>{"a", "a/b", "a/b/figure.bin"});
}

TEST_CASE("write_file_atomically replaces an existing file and writes empty files",
          "[common][image_io][files]") {
  const testing::ScratchFolder scratch("replaces");
  const fs::path& folder = scratch.path();
  const fs::path path = folder / "data.txt";
  write_file_atomically(path, bytes_of("the old, longer content"));
  write_file_atomically(path, bytes_of("new"));
  CHECK(read_file(path) == bytes_of("new"));
  write_file_atomically(path, std::vector<std::uint8_t>{});
  CHECK(fs::exists(path));
  CHECK(fs::file_size(path) == 0);
  CHECK(files_below(folder) == std::vector<std::string>{"data.txt"});
}

TEST_CASE("write_file_atomically below a regular file fails, names the path, writes nothing",
          "[common][image_io][files]") {
  const testing::ScratchFolder scratch("below_a_file");
  const fs::path& folder = scratch.path();
  const fs::path blocker = folder / "blocker";
  std::ofstream(blocker) << "not a folder";
  const fs::path path = blocker / "sub" / "figure.png";

  CHECK_THROWS_AS(write_file_atomically(path, bytes_of("png")), std::runtime_error);
  CHECK_THROWS_WITH(write_file_atomically(path, bytes_of("png")), Catch::Contains(path.string()));
  CHECK(files_below(folder) == std::vector<std::string>{"blocker"});
  CHECK(read_file(blocker) == bytes_of("not a folder"));
}

TEST_CASE("write_file_atomically onto an existing folder fails, names the path, leaves no .tmp",
          "[common][image_io][files]") {
  const testing::ScratchFolder scratch("onto_a_folder");
  const fs::path& folder = scratch.path();
  const fs::path path = folder / "taken";
  fs::create_directory(path);

  CHECK_THROWS_AS(write_file_atomically(path, bytes_of("png")), std::runtime_error);
  CHECK_THROWS_WITH(write_file_atomically(path, bytes_of("png")), Catch::Contains(path.string()));
  CHECK(fs::is_directory(path));
  CHECK(files_below(folder) == std::vector<std::string>{"taken"});
}

TEST_CASE("write_png and write_counts_pgm write exactly the encoded bytes",
          "[common][image_io][files]") {
  const testing::ScratchFolder scratch("write_png");
  const fs::path& folder = scratch.path();
  Canvas canvas = numbered_canvas();
  canvas.enable_write_counts();
  canvas.put_pixel(4, 2, colors::red);
  write_png(canvas, folder / "picture.png");
  write_counts_pgm(canvas, folder / "counts.pgm");
  CHECK(read_file(folder / "picture.png") == encode_png(canvas));
  CHECK(read_file(folder / "counts.pgm") == encode_counts_pgm(canvas));
  CHECK(files_below(folder) == std::vector<std::string>{"counts.pgm", "picture.png"});
}

TEST_CASE("write_counts_pgm without write counts fails and writes nothing",
          "[common][image_io][files]") {
  const testing::ScratchFolder scratch("no_counts");
  const fs::path& folder = scratch.path();
  CHECK_THROWS_AS(write_counts_pgm(Canvas(2, 2), folder / "counts.pgm"), std::logic_error);
  CHECK(files_below(folder).empty());
}

TEST_CASE("Seeded random canvases encode to PNGs and PGMs that decode to their pixels and counts",
          "[common][image_io][png]") {
  Random random(31);
  for (int trial = 0; trial < 60; ++trial) {
    const int width = trial == 0 ? 300 : random.integer(1, 64);
    const int height = trial == 1 ? 200 : random.integer(1, 64);
    CAPTURE(trial, width, height);
    Canvas canvas(width, height);
    canvas.enable_write_counts();
    // Runs of one colour (what a drawing has) and noise (what compresses worst), counts to 300.
    Color color{};
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        if (random.integer(0, 7) == 0 || trial % 2 == 1) {
          color = {static_cast<std::uint8_t>(random.integer(0, 255)),
                   static_cast<std::uint8_t>(random.integer(0, 255)),
                   static_cast<std::uint8_t>(random.integer(0, 255)),
                   static_cast<std::uint8_t>(random.integer(0, 255))};
        }
        const int writes = random.integer(0, 3) == 0 ? random.integer(0, 300) : 1;
        for (int w = 0; w < writes; ++w) canvas.put_pixel(x, y, color);
      }
    }
    const std::vector<std::uint8_t> png = encode_png(canvas);
    const std::vector<std::string> chunks = checked_chunks(png);
    REQUIRE(chunks.size() >= 3);
    CHECK(chunks.front() == "IHDR");
    CHECK(chunks.back() == "IEND");
    const DecodedPng decoded = decode_png(png);
    REQUIRE(decoded.decoded);
    CHECK(decoded.width == width);
    CHECK(decoded.height == height);
    const std::vector<std::uint8_t> pgm = encode_counts_pgm(canvas);
    const std::string header =
        "P5\n" + std::to_string(width) + " " + std::to_string(height) + "\n255\n";
    REQUIRE(pgm.size() == header.size() + static_cast<std::size_t>(width * height));
    CHECK(std::string(pgm.begin(), pgm.begin() + static_cast<std::ptrdiff_t>(header.size())) ==
          header);
    int wrong_pixels = 0, wrong_counts = 0;
    for (int row = 0; row < height; ++row) {
      const int y = height - 1 - row;  // top row first
      for (int x = 0; x < width; ++x) {
        const Color c = canvas.pixel(x, y);
        const std::size_t k = static_cast<std::size_t>(row * width + x);
        wrong_pixels += !std::equal(decoded.rgba.begin() + static_cast<std::ptrdiff_t>(4 * k),
                                    decoded.rgba.begin() + static_cast<std::ptrdiff_t>(4 * k + 4),
                                    std::vector<std::uint8_t>{c.r, c.g, c.b, c.a}.begin());
        wrong_counts += pgm[header.size() + k] != std::min(canvas.write_count(x, y), 255u);
      }
    }
    CHECK(wrong_pixels == 0);
    CHECK(wrong_counts == 0);
  }
}

}  // namespace tri
