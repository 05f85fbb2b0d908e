/// @file
/// The write ceiling: how fast this machine writes every byte of a canvas at all, the bound for
/// any rasterizer that stores 4 bytes per covered pixel. Two fills are timed and the faster one
/// is the ceiling: the C library's memset (whose code is chosen for the host at run time: wide
/// vector stores, and the processor's string store for long buffers) and chapter 08's
/// fill_pixels over whole rows (16-byte stores of one colour word, the portable build's widest).
#pragma once

#include <algorithm>
#include <array>
#include <functional>
#include <string_view>
#include <vector>

#include "common/canvas.hpp"
#include "measure/timing.hpp"

namespace tri {

/// The two fills the ceiling is the faster of.
enum class CeilingFill { memset, vector_stores };
inline constexpr std::array<CeilingFill, 2> ceiling_fills{CeilingFill::memset,
                                                          CeilingFill::vector_stores};

/// "memset" or "vector stores", as the tables print it.
std::string_view name_of(CeilingFill fill) noexcept;

/// One fill of every pixel of the canvas, split into `threads` bands of rows, each written by a
/// thread started for this fill (as a threaded algorithm starts its own for every batch; 1: the
/// calling thread). Every call writes a new value, so no fill repeats the one before.
std::function<void()> ceiling_fill_run(Canvas& canvas, CeilingFill fill, int threads);

/// A canvas's write ceiling in Mpixels/s: each fill's rate, and the faster as the ceiling.
struct FillCeiling {
  double memset_mpix_per_s = 0;
  double vector_stores_mpix_per_s = 0;

  double mpix_per_s() const noexcept {
    return std::max(memset_mpix_per_s, vector_stores_mpix_per_s);
  }
};

/// The ceiling from the two fills' timings (memset first, as ceiling_fills lists them) over a
/// canvas of `pixels` pixels.
FillCeiling fill_ceiling_of(double pixels, const Timing& memset, const Timing& vector_stores);

/// Times both fills of the canvas against each other in interleaved rounds (counting must be off):
/// one Timing per fill, in the order of ceiling_fills.
std::vector<Timing> time_ceiling_fills(Canvas& canvas, int threads, const TimingPlan& plan);

/// The ceiling from time_ceiling_fills.
FillCeiling measure_fill_ceiling(Canvas& canvas, int threads, const TimingPlan& plan);

}  // namespace tri
