#include "algorithms.hpp"

namespace tri::ch03 {

std::span<const TriangleAlgorithm> triangle_algorithms() { return {}; }

}  // namespace tri::ch03
