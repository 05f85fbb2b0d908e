#include "chapters/10_speed_vs_error/report_csv.hpp"

#include <array>
#include <string>

namespace tri::ch10 {
namespace {

constexpr std::array<std::string_view, 31> columns{"algorithm",
                                                   "chapter",
                                                   "rule",
                                                   "threaded",
                                                   "scene",
                                                   "grid",
                                                   "mesh",
                                                   "canvas",
                                                   "triangles",
                                                   "covered_pixels",
                                                   "written_pixels",
                                                   "repetitions",
                                                   "samples",
                                                   "median_s",
                                                   "min_s",
                                                   "max_s",
                                                   "tris_per_s",
                                                   "mpix_per_s",
                                                   "fill_ceiling_mpix_per_s",
                                                   "ratio_to_ceiling",
                                                   "error_triangles",
                                                   "missed",
                                                   "extra",
                                                   "gaps",
                                                   "overdraw",
                                                   "order_dependent",
                                                   "outside_writes",
                                                   "rejected",
                                                   "error_rate",
                                                   "wrong_pixels",
                                                   "exact"};

}  // namespace

std::string seconds_columns(const Timing& timing) {
  return format_number(timing.seconds.median, 6) + ',' + format_number(timing.seconds.min, 6) +
         ',' + format_number(timing.seconds.max, 6);
}

std::string quoted_text(std::string_view text) {
  std::string field = "\"";
  for (const char c : text) field += c == '"' ? std::string("\"\"") : std::string(1, c);
  return field + "\"";
}

std::string canvas_column(int width, int height) {
  return std::to_string(width) + 'x' + std::to_string(height);
}

std::span<const std::string_view> csv_columns() noexcept {
  return columns;
}

std::string to_csv(std::span<const Measurement> rows) {
  std::string header;
  for (std::string_view column : columns) {
    if (!header.empty()) header += ',';
    header += column;
  }
  return csv_table(header, rows, [](const Measurement& m) {
    const ErrorReport& e = m.error;
    return std::tuple(m.algorithm, m.chapter, m.rule, m.threaded ? 1 : 0, m.scene, m.grid,
                      m.mesh ? 1 : 0, canvas_column(m.width, m.height), m.triangles, e.covered,
                      m.written_pixels, m.timing.repetitions, m.timing.samples,
                      seconds_columns(m.timing), format_number(m.triangles_per_second(), 6),
                      format_number(m.mpix_per_second(), 6),
                      format_number(m.fill_ceiling_mpix_per_s, 6),
                      format_number(m.ratio_to_ceiling(), 4), m.error_triangles, e.missed, e.extra,
                      e.gaps, e.overdraw, e.order_dependent, e.outside_writes, e.rejected,
                      format_number(e.error_rate(), 6), e.missed + e.extra, e.exact() ? 1 : 0);
  });
}

}  // namespace tri::ch10
