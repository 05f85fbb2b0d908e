#include "fuzz/scene_parser_check.hpp"

#include <cmath>
#include <exception>
#include <sstream>
#include <variant>

#include "common/canvas.hpp"
#include "common/triangle_algorithm.hpp"

namespace tri::fuzz {
namespace {

bool within_limits(double coordinate) noexcept {
  return std::isfinite(coordinate) && std::abs(coordinate) <= max_scene_coordinate;
}

std::string position(std::size_t index) {
  return "primitive " + std::to_string(index);
}

}  // namespace

Findings check_scene_contract(const Scene& scene, const SceneLimits& limits) {
  Findings findings;
  if (scene.primitives.size() > limits.max_primitives) {
    findings.push_back("returned " + std::to_string(scene.primitives.size()) +
                       " primitives, more than the limit " + std::to_string(limits.max_primitives));
  }
  const auto side_ok = [](int side) { return side >= 1 && side <= max_canvas_side; };
  if (!side_ok(scene.width) || !side_ok(scene.height)) {
    findings.push_back("returned a " + std::to_string(scene.width) + "x" +
                       std::to_string(scene.height) + " canvas, outside 1..16384");
  }
  for (std::size_t i = 0; i < scene.primitives.size(); ++i) {
    const auto* triangle = std::get_if<SceneTriangle>(&scene.primitives[i]);
    const auto* line = std::get_if<SceneLine>(&scene.primitives[i]);
    bool ok = true;
    if (triangle != nullptr) {
      for (const glm::dvec2& v : triangle->vertices)
        ok = ok && within_limits(v.x) && within_limits(v.y);
      if (validate_triangle(triangle->vertices) != DrawResult::drawn) {
        findings.push_back("returned a triangle at " + position(i) +
                           " that validate_triangle refuses");
      }
    } else {
      for (const glm::dvec2& p : line->ends) ok = ok && within_limits(p.x) && within_limits(p.y);
    }
    if (!ok) {
      findings.push_back("returned a non-finite coordinate or one beyond ±2^30 at " + position(i));
    }
  }
  return findings;
}

namespace {

void check_error_message(const std::string& message, Findings& findings) {
  const std::string prefix = std::string(fuzz_source_name) + ":";
  if (message.rfind(prefix, 0) != 0) {
    findings.push_back("SceneError message does not start with '" + prefix + "': " + message);
  }
  if (message.find('\n') != std::string::npos) {
    findings.push_back("SceneError message spans more than one line: " + message);
  }
  // Scene words are shown as short escaped excerpts: no control byte, no runaway length.
  for (const char c : message) {
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F) {
      findings.push_back("SceneError message has a raw control character: " + message);
      break;
    }
  }
  if (message.size() > 512) {
    findings.push_back("SceneError message is longer than 512 bytes: " + message.substr(0, 512));
  }
}

}  // namespace

namespace {

// One parse with the given limits: whether a scene came back, and the SceneError message if any.
bool parse_and_check(std::string_view text, const SceneLimits& limits, std::string& error,
                     Findings& findings) {
  std::istringstream in{std::string(text)};
  try {
    const Scene scene = parse_scene(in, fuzz_source_name, limits);
    const Findings broken = check_scene_contract(scene, limits);
    findings.insert(findings.end(), broken.begin(), broken.end());
    return true;
  } catch (const SceneError& e) {
    error = e.what();
    check_error_message(error, findings);
  } catch (const std::exception& e) {
    findings.push_back(std::string("threw an exception other than SceneError: ") + e.what());
  } catch (...) {
    findings.push_back("threw something that is not a std::exception");
  }
  return false;
}

}  // namespace

ParseOutcome check_scene_parser(std::string_view text) {
  ParseOutcome outcome;
  outcome.parsed = parse_and_check(text, SceneLimits{}, outcome.error, outcome.findings);
  parse_and_check(text, fuzz_scene_limits, outcome.small_limits_error, outcome.findings);
  return outcome;
}

}  // namespace tri::fuzz
