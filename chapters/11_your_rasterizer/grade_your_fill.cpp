#include "chapters/11_your_rasterizer/grade_your_fill.hpp"

#include <algorithm>
#include <string>

#include "chapters/11_your_rasterizer/conformance_app.hpp"
#include "chapters/11_your_rasterizer/grading.hpp"
#include "chapters/11_your_rasterizer/your_fill.hpp"

namespace tri::ch11 {

bool draws_anything(const conformance::FillFunction& fill) {
  Canvas canvas(12, 12);
  canvas.enable_write_counts();
  fill(canvas, {glm::dvec2{1.5, 1.5}, glm::dvec2{10.5, 1.5}, glm::dvec2{1.5, 10.5}}, colors::white);
  const auto counts = canvas.write_counts();
  return std::any_of(counts.begin(), counts.end(), [](std::uint32_t c) { return c > 0; });
}

int grade_fill(const std::string& name, const conformance::FillFunction& fill,
               conformance::TieRule rule, const std::filesystem::path& folder, std::ostream& out,
               std::ostream& err) {
  if (!draws_anything(fill)) {
    err << name << " draws no pixel yet, so every test that expects pixels fails. Write its body "
        << "in chapters/11_your_rasterizer/your_fill.cpp (the chapter's README, step 2, starts "
        << "you off), build 11_your_rasterizer again and run this command again.\n";
  }
  return conformance::run_suite(conformance::graded_fill(name, fill), rule,
                                conformance::default_time_limit, folder, out, err);
}

int grade_your_fill(conformance::TieRule rule, const std::filesystem::path& folder,
                    std::ostream& out, std::ostream& err) {
  return grade_fill("your_fill", your_fill, rule, folder, out, err);
}

}  // namespace tri::ch11
