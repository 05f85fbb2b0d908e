#include "measure/fill_ceiling.hpp"

#include <bit>
#include <cstdint>
#include <cstring>
#include <memory>
#include <span>
#include <thread>
#include <vector>

#include "chapters/08_fast_exact/pixel_writers.hpp"

namespace tri {
namespace {

// [listing ceiling_fills]
// Rows first_row <= y < end_row, with memset of one byte value or with chapter 08's 16-byte
// stores of one colour word.
void fill_rows(Canvas& canvas, int first_row, int end_row, CeilingFill fill, std::uint8_t shade) {
  const Color color{shade, static_cast<std::uint8_t>(255 - shade), 128, 255};
  const auto word = std::bit_cast<std::uint32_t>(color);
  for (int y = first_row; y < end_row; ++y) {
    const std::span<Color> row = canvas.row(y);
    if (fill == CeilingFill::memset) {
      std::memset(row.data(), shade, row.size_bytes());
    } else {
      ch08::fill_pixels(row.data(), static_cast<int>(row.size()), word);
    }
  }
}
// [/listing]

}  // namespace

std::string_view name_of(CeilingFill fill) noexcept {
  return fill == CeilingFill::memset ? "memset" : "vector stores";
}

std::function<void()> ceiling_fill_run(Canvas& canvas, CeilingFill fill, int threads) {
  auto shade = std::make_shared<std::uint8_t>(0);
  const int bands = std::clamp(threads, 1, std::max(1, canvas.height()));
  return [&canvas, fill, bands, shade] {
    const std::uint8_t value = ++*shade;
    if (bands == 1) return fill_rows(canvas, 0, canvas.height(), fill, value);
    std::vector<std::jthread> workers;
    workers.reserve(static_cast<std::size_t>(bands));
    for (int band = 0; band < bands; ++band) {
      const int first = canvas.height() * band / bands;
      const int end = canvas.height() * (band + 1) / bands;
      workers.emplace_back(
          [&canvas, first, end, fill, value] { fill_rows(canvas, first, end, fill, value); });
    }
  };
}

FillCeiling fill_ceiling_of(double pixels, const Timing& memset, const Timing& vector_stores) {
  return {mpix_per_second(pixels, memset.seconds.median),
          mpix_per_second(pixels, vector_stores.seconds.median)};
}

std::vector<Timing> time_ceiling_fills(Canvas& canvas, int threads, const TimingPlan& plan) {
  std::vector<std::function<void()>> runs;
  for (const CeilingFill fill : ceiling_fills)
    runs.push_back(ceiling_fill_run(canvas, fill, threads));
  return time_interleaved(runs, plan);
}

FillCeiling measure_fill_ceiling(Canvas& canvas, int threads, const TimingPlan& plan) {
  const std::vector<Timing> timings = time_ceiling_fills(canvas, threads, plan);
  return fill_ceiling_of(static_cast<double>(canvas.width()) * canvas.height(), timings[0],
                         timings[1]);
}

}  // namespace tri
