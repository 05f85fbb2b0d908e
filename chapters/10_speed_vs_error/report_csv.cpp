#include "chapters/10_speed_vs_error/report_csv.hpp"

#include <array>
#include <sstream>

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

std::span<const std::string_view> csv_columns() noexcept {
  return columns;
}

std::string to_csv(std::span<const Measurement> rows) {
  std::ostringstream csv;
  for (std::size_t i = 0; i < columns.size(); ++i) csv << (i == 0 ? "" : ",") << columns[i];
  csv << '\n';
  for (const Measurement& m : rows) {
    const ErrorReport& e = m.error;
    csv << m.algorithm << ',' << m.chapter << ',' << m.rule << ',' << (m.threaded ? 1 : 0) << ','
        << m.scene << ',' << m.grid << ',' << (m.mesh ? 1 : 0) << ',' << m.width << 'x' << m.height
        << ',' << m.triangles << ',' << e.covered << ',' << m.written_pixels << ','
        << m.timing.repetitions << ',' << m.timing.samples << ','
        << format_number(m.timing.seconds.median, 6) << ','
        << format_number(m.timing.seconds.min, 6) << ',' << format_number(m.timing.seconds.max, 6)
        << ',' << format_number(m.triangles_per_second(), 6) << ','
        << format_number(m.mpix_per_second(), 6) << ','
        << format_number(m.fill_ceiling_mpix_per_s, 6) << ','
        << format_number(m.ratio_to_ceiling(), 4) << ',' << m.error_triangles << ',' << e.missed
        << ',' << e.extra << ',' << e.gaps << ',' << e.overdraw << ',' << e.order_dependent << ','
        << e.outside_writes << ',' << e.rejected << ',' << format_number(e.error_rate(), 6) << ','
        << e.missed + e.extra << ',' << (e.exact() ? 1 : 0) << '\n';
  }
  return csv.str();
}

}  // namespace tri::ch10
