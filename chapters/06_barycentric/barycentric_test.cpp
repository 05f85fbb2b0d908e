#include <array>
#include <cmath>
#include <limits>

#include <catch2/catch.hpp>

#include "chapters/06_barycentric/barycentric.hpp"
#include "chapters/06_barycentric/examples.hpp"
#include "chapters/06_barycentric/random_triangles.hpp"
#include "tests/support/pixels.hpp"

using namespace tri::ch06;
using namespace tri::testing;

TEST_CASE("The cross product of the two rows holds both weights and twice the area",
          "[06_barycentric][step2][06][barycentric]") {
  const auto [a, b, c] = hand_checked_triangle;
  // P - A = (2, 2) = 2/9 AB + 4/9 AC, and AB x AC = 5*4 - 2*1 = 18.
  CHECK(cross_of_rows<double>(a, b, c, {3, 3}) == glm::dvec3(4, 8, 18));
  CHECK(cross_of_rows<float>(a, b, c, {3, 3}) == glm::vec3(4, 8, 18));
  // The area does not depend on P.
  CHECK(cross_of_rows<double>(a, b, c, {-40, 7}).z == 18);
}

TEST_CASE("The weights of a hand-checked point are 1/3, 2/9 and 4/9",
          "[06_barycentric][step2][06][barycentric]") {
  const auto [a, b, c] = hand_checked_triangle;
  const Weights<double> w = barycentric<double>(a, b, c, {3, 3});
  CHECK(w.x == Approx(1.0 / 3.0).epsilon(1e-15));
  CHECK(w.y == 4.0 / 18.0);
  CHECK(w.z == 8.0 / 18.0);
}

TEST_CASE("The article's return order puts C's weight second, ours is A, B, C",
          "[06_barycentric][traps][06][barycentric]") {
  // The article returns (1 - (u.x + u.y)/u.z, u.y/u.z, u.x/u.z): with its rows starting AB, AC,
  // u.x/u.z belongs to B, so its vector reads (A, C, B). At P = B that shows as (0, 0, 1).
  const glm::ivec2 a(0, 0), b(1, 0), c(0, 1);
  const glm::dvec3 u = cross_of_rows<double>(a, b, c, b);
  const glm::dvec3 article_order(1 - (u.x + u.y) / u.z, u.y / u.z, u.x / u.z);
  CHECK(article_order == glm::dvec3(0, 0, 1));
  CHECK(barycentric<double>(a, b, c, b) == Weights<double>(0, 1, 0));
}

TEST_CASE("Each vertex has the weights (1,0,0), (0,1,0), (0,0,1) exactly, even at 2^30",
          "[06_barycentric][step2][06][barycentric]") {
  Random random(601);
  int checked = 0;
  for (int i = 0; i < 2000; ++i) {
    const int reach = i < 1000 ? 300 : (1 << 30);
    const auto [a, b, c] = random_vertices(random, -reach, reach);
    // Skip zero areas, and huge areas that double itself rounds to zero (the guard's case).
    if (doubled_area(a, b, c) == 0 || cross_of_rows<double>(a, b, c, a).z == 0) continue;
    ++checked;
    CHECK(barycentric<double>(a, b, c, a) == Weights<double>(1, 0, 0));
    CHECK(barycentric<double>(a, b, c, b) == Weights<double>(0, 1, 0));
    CHECK(barycentric<double>(a, b, c, c) == Weights<double>(0, 0, 1));
    // Float may round a huge area to zero; when it does not, the vertices are still exact.
    if (cross_of_rows<float>(a, b, c, a).z == 0) continue;
    CHECK(barycentric<float>(a, b, c, a) == Weights<float>(1, 0, 0));
    CHECK(barycentric<float>(a, b, c, b) == Weights<float>(0, 1, 0));
    CHECK(barycentric<float>(a, b, c, c) == Weights<float>(0, 0, 1));
  }
  CHECK(checked == 2000);
}

TEST_CASE("The weights sum to 1 and rebuild the pixel they were computed for",
          "[06_barycentric][step2][06][barycentric]") {
  Random random(602);
  for (int i = 0; i < 2000; ++i) {
    const auto [a, b, c] = random_vertices(random, -1000, 1000);
    const glm::ivec2 p = random_point(random, -1000, 1000);
    if (doubled_area(a, b, c) == 0) continue;
    const Weights<double> w = barycentric<double>(a, b, c, p);
    CHECK(std::abs(w.x + w.y + w.z - 1) < 1e-9);
    const glm::dvec2 rebuilt = w.x * glm::dvec2(a) + w.y * glm::dvec2(b) + w.z * glm::dvec2(c);
    CHECK(std::abs(rebuilt.x - p.x) < 1e-6);
    CHECK(std::abs(rebuilt.y - p.y) < 1e-6);
  }
}

TEST_CASE("Swapping two vertices swaps their weights, whatever the winding",
          "[06_barycentric][step2][06][barycentric]") {
  const auto [a, b, c] = hand_checked_triangle;
  const glm::ivec2 p(3, 3);
  const Weights<double> abc = barycentric<double>(a, b, c, p);
  const Weights<double> acb = barycentric<double>(a, c, b, p);
  const Weights<double> cab = barycentric<double>(c, a, b, p);
  CHECK(acb.x == Approx(abc.x));
  CHECK(acb.y == Approx(abc.z));
  CHECK(acb.z == Approx(abc.y));
  CHECK(cab.x == Approx(abc.z));
  CHECK(cab.y == Approx(abc.x));
  CHECK(cab.z == Approx(abc.y));
}

TEST_CASE("A zero-area triangle gets the weights (-1,1,1) from the guard",
          "[06_barycentric][step2][06][barycentric]") {
  const std::array<std::array<glm::ivec2, 3>, 5> degenerate{{
      {{{0, 0}, {0, 0}, {0, 0}}},  // all three equal
      {{{2, 2}, {2, 2}, {9, 6}}},  // two equal
      {{{1, 2}, {9, 2}, {5, 2}}},  // horizontal
      {{{4, 0}, {4, 9}, {4, 3}}},  // vertical
      {{{1, 1}, {3, 2}, {9, 5}}},  // diagonal
  }};
  for (const auto& [a, b, c] : degenerate) {
    for (const glm::ivec2 p : {a, b, c, glm::ivec2(5, 3), glm::ivec2(0, 7)}) {
      CHECK(barycentric<double>(a, b, c, p) == degenerate_weights<double>);
      CHECK(barycentric<float>(a, b, c, p) == degenerate_weights<float>);
      CHECK_FALSE(is_inside(barycentric<double>(a, b, c, p)));
    }
  }
}

TEST_CASE("The smallest non-zero area of integer vertices passes the guard",
          "[06_barycentric][traps][06][barycentric]") {
  // Twice the area is a whole number: 0 or at least 1. So the guard's threshold belongs between
  // 0 and 1 - any float epsilon, 1e-7 or 1e-45, lands there only because of that.
  const glm::ivec2 a(0, 0), b(1, 0), c(0, 1);
  CHECK(cross_of_rows<float>(a, b, c, a).z == 1);
  CHECK(barycentric<float>(a, b, c, a) == Weights<float>(1, 0, 0));
  CHECK(barycentric<double>({0, 0}, {2, 1}, {4, 3}, {2, 1}) == Weights<double>(0, 1, 0));
}

TEST_CASE("The inside test keeps zero weights and rejects a negative one",
          "[06_barycentric][step2][06][inside]") {
  CHECK(is_inside(Weights<double>(1, 0, 0)));
  CHECK(is_inside(Weights<double>(0.5, 0.5, 0)));
  CHECK(is_inside(Weights<double>(0.5, 0.5, -0.0)));
  CHECK_FALSE(is_inside(Weights<double>(1.5, -0.5, 0)));
  CHECK_FALSE(is_inside(Weights<float>(-1e-30f, 0.5f, 0.5f)));
}

TEST_CASE("NaN weights pass the inside test, because every comparison with NaN is false",
          "[06_barycentric][step3][06][inside]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  CHECK(is_inside(Weights<double>(nan, nan, nan)));
  CHECK(is_inside(Weights<double>(nan, 0.5, 0.5)));
  CHECK(is_inside(Weights<double>(inf, nan, 0)));
  CHECK_FALSE(is_inside(Weights<double>(-inf, nan, inf)));
}

TEST_CASE("Without the guard a zero area gives NaN on the line and opposite infinities off it",
          "[06_barycentric][step2][06][barycentric]") {
  const glm::ivec2 a(1, 1), b(9, 5), c(3, 2);
  // (5, 3) lies on the line: every weight is 0/0.
  const Weights<double> on_line = barycentric_unguarded<double>(a, b, c, {5, 3});
  CHECK(std::isnan(on_line.x));
  CHECK(std::isnan(on_line.y));
  CHECK(std::isnan(on_line.z));
  CHECK(is_inside(on_line));
  // Off the line the numerators sum to 0, so one of them is negative and gives -infinity.
  const Weights<double> off_line = barycentric_unguarded<double>(a, b, c, {5, 4});
  CHECK(std::isinf(off_line.x));
  CHECK(std::isinf(off_line.y));
  CHECK(std::isinf(off_line.z));
  CHECK_FALSE(is_inside(off_line));
}
