/// @file
/// Gambetta's Interpolate: the one helper both his lines and his filled triangles are built on.
#pragma once

#include <vector>

namespace tri::ch01 {

/// The values of a linear function d(i) with d(i0) = d0 and d(i1) = d1, sampled at every integer
/// i from i0 to i1 **inclusive** (i1 - i0 + 1 values; i0 <= i1). With i0 == i1 the slope is
/// undefined, so the single value d0 is returned. Like the book, it steps by adding the slope,
/// and it allocates the vector it returns.
std::vector<double> interpolate(int i0, double d0, int i1, double d1);

}  // namespace tri::ch01
