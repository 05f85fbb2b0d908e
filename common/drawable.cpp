#include "common/drawable.hpp"

namespace tri {

std::string_view rule_name(CoverageRule rule) noexcept {
  switch (rule) {
    case CoverageRule::top_left:
      return "top-left";
    case CoverageRule::bottom_left:
      return "bottom-left";
    case CoverageRule::inclusive:
      return "inclusive";
    case CoverageRule::approximate:
      return "approximate";
    case CoverageRule::area:
      return "area";
  }
  return "approximate";
}

}  // namespace tri
