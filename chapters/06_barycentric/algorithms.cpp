#include "algorithms.hpp"

namespace tri::ch06 {

std::span<const TriangleAlgorithm> triangle_algorithms() { return {}; }

}  // namespace tri::ch06
