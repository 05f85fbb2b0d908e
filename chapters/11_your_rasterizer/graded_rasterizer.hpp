/// @file
/// What the suite grades: anything that draws a scene's triangles and answers with its write
/// counts, refuses the scene, or fails. A registered algorithm, a C++ fill function and an
/// external program (command_rasterizer.hpp) are each made into one.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "common/canvas.hpp"
#include "common/scene.hpp"
#include "common/triangle_algorithm.hpp"

namespace tri::conformance {

/// What one drawing of a scene gave.
struct Answer {
  enum class Kind {
    counts,   ///< the write counts of every pixel
    refused,  ///< the rasterizer refused the scene and said why (a non-zero exit with a message)
    failed,   ///< it crashed, hung, or answered something unreadable
  };
  Kind kind = Kind::counts;
  std::vector<std::uint32_t> counts;  ///< bottom row first, as Canvas::write_counts
  std::string reason;                 ///< why it refused or failed
};

/// How many threads a drawing may use, for the determinism test.
enum class Threads { all, one };

/// The latest moment an answer is waited for.
using Deadline = std::chrono::steady_clock::time_point;

/// A rasterizer under test: its name, whether it draws with threads, and how it draws a scene.
struct GradedRasterizer {
  std::string name;
  bool threaded = false;  ///< the determinism test also draws with Threads::one
  std::function<Answer(const Scene& scene, Threads threads, Deadline deadline)> draw;
};

/// A registered algorithm (which must outlive the result): Threads::all draws through a BatchDrawer
/// (its batch or threaded entry), Threads::one draws triangle after triangle through its
/// one-triangle entry. Refused triangles (NaN, infinite, beyond ±2^30) draw nothing, as
/// draw_triangle promises.
GradedRasterizer graded_algorithm(const TriangleAlgorithm& algorithm);

/// A fill function, as chapter 11's learner writes it: one triangle on a canvas, in one colour.
using FillFunction = std::function<void(Canvas& canvas, const Triangle& triangle, Color color)>;

/// A fill function outside the registry, called once per triangle in scene order on a counting
/// canvas. Triangles that validate_triangle refuses never reach it, as with the registry's entry
/// point, so a fill only needs to handle finite vertices within ±2^30.
GradedRasterizer graded_fill(std::string name, FillFunction fill);

}  // namespace tri::conformance
