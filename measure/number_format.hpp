/// @file
/// Numbers as the report's CSV, tables and plots write them.
#pragma once

#include <string>

namespace tri {

/// A number with `significant` significant digits, "%g" style.
std::string format_number(double value, int significant = 4);

}  // namespace tri
