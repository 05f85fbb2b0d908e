#include "algorithms.hpp"

namespace tri::ch04 {

std::span<const TriangleAlgorithm> triangle_algorithms() { return {}; }

}  // namespace tri::ch04
