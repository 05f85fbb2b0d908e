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

Findings check_scene_contract(const Scene& scene) {
  Findings findings;
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

ParseOutcome check_scene_parser(std::string_view text) {
  ParseOutcome outcome;
  std::istringstream in{std::string(text)};
  try {
    const Scene scene = parse_scene(in, fuzz_source_name);
    outcome.parsed = true;
    outcome.findings = check_scene_contract(scene);
  } catch (const SceneError& e) {
    outcome.error = e.what();
    check_error_message(outcome.error, outcome.findings);
  } catch (const std::exception& e) {
    outcome.findings.push_back(std::string("threw an exception other than SceneError: ") +
                               e.what());
  } catch (...) {
    outcome.findings.push_back("threw something that is not a std::exception");
  }
  return outcome;
}

}  // namespace tri::fuzz
