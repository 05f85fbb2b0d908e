/// @file
/// The check that a drawing matched the oracle: nothing missed or extra, no gap, no overdraw,
/// nothing that depends on the order. One CHECK per kind, so that a failure names the kind.
#pragma once

#include <catch2/catch.hpp>

#include "measure/error_metrics.hpp"

namespace tri::testing {

inline void check_no_deviation(const ErrorReport& error) {
  CHECK(error.missed == 0);
  CHECK(error.extra == 0);
  CHECK(error.gaps == 0);
  CHECK(error.overdraw == 0);
  CHECK(error.order_dependent == 0);
}

}  // namespace tri::testing
