#include "chapters/01_lines/interpolate.hpp"

#include <cstdint>

namespace tri::ch01 {

// [listing interpolate]
std::vector<double> interpolate(int i0, double d0, int i1, double d1) {
  if (i0 == i1) return {d0};  // one sample; (d1 - d0) / 0 would be the slope otherwise
  std::vector<double> values;
  const auto steps = static_cast<double>(i1) - i0;  // in double: i1 - i0 may overflow int
  values.reserve(static_cast<std::size_t>(steps) + 1);
  const double slope = (d1 - d0) / steps;
  double d = d0;
  for (std::int64_t i = i0; i <= i1; ++i) {  // <=: the port's `i < i1` loses the last sample
    values.push_back(d);
    d += slope;
  }
  return values;
}
// [/listing]

}  // namespace tri::ch01
