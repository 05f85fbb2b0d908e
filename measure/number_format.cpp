#include "measure/number_format.hpp"

#include <cstdio>

namespace tri {

std::string format_number(double value, int significant) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*g", significant, value);
  return text;
}

}  // namespace tri
