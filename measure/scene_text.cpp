#include "measure/scene_text.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <stdexcept>
#include <variant>

namespace tri {
namespace {

std::string number(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return std::string(buffer.data(), result.ptr);
}

std::string colour(Color c) {
  return std::to_string(c.r) + " " + std::to_string(c.g) + " " + std::to_string(c.b);
}

}  // namespace

std::string scene_text(const Scene& scene) {
  std::string text = "canvas " + std::to_string(scene.width) + " " + std::to_string(scene.height) +
                     " " + colour(scene.background) + "\n";
  for (const auto& primitive : scene.primitives) {
    const auto* t = std::get_if<SceneTriangle>(&primitive);
    if (t == nullptr) continue;
    text += "tri";
    for (const auto& v : t->vertices) text += " " + number(v.x) + " " + number(v.y);
    text += " " + colour(t->color) + "\n";
  }
  return text;
}

void write_scene_file(const std::filesystem::path& path, const Scene& scene) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!(out << scene_text(scene)).flush())
    throw std::runtime_error("cannot write the scene file " + path.string());
}

}  // namespace tri
