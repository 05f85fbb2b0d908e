#include "common/drawable.hpp"

#include "common/enum_names.hpp"

namespace tri {

namespace {

constexpr auto rule_names =
    all_names<CoverageRule::area>({{CoverageRule::top_left, "top-left"},
                                   {CoverageRule::bottom_left, "bottom-left"},
                                   {CoverageRule::inclusive, "inclusive"},
                                   {CoverageRule::approximate, "approximate"},
                                   {CoverageRule::area, "area"}});

}  // namespace

std::string_view rule_name(CoverageRule rule) noexcept {
  return name_in(rule_names, rule, "approximate");
}

}  // namespace tri
