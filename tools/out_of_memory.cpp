#include "tools/out_of_memory.hpp"

#include <sstream>

namespace tri {

std::string human_bytes(double bytes) {
  const char* units[] = {"bytes", "KiB", "MiB", "GiB", "TiB"};
  int unit = 0;
  while (bytes >= 1024 && unit < 4) {
    bytes /= 1024;
    ++unit;
  }
  std::ostringstream text;
  text.setf(std::ios::fixed);
  text.precision(unit == 0 ? 0 : 1);
  text << bytes << ' ' << units[unit];
  return text.str();
}

}  // namespace tri
