#include "algorithms.hpp"

namespace tri::ch08 {

std::span<const TriangleAlgorithm> triangle_algorithms() {
  return {};
}

}  // namespace tri::ch08
