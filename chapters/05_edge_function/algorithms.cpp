#include "algorithms.hpp"

namespace tri::ch05 {

std::span<const TriangleAlgorithm> triangle_algorithms() { return {}; }

}  // namespace tri::ch05
