#include <catch2/catch.hpp>

#include <algorithm>
#include <vector>

#include "chapters/08_fast_exact/hybrid.hpp"
#include "chapters/08_fast_exact/test_triangles.hpp"
#include "chapters/08_fast_exact/threaded.hpp"

using tri::Canvas;
using tri::SceneTriangle;

using tri::ch08::testing::drawn_on;
using tri::ch08::testing::overlapping_scene;
using tri::ch08::testing::same_canvas;

TEST_CASE("bands are 16 to 64 rows, about four per thread, dealt to the threads in turn",
          "[08_fast_exact][step7]") {
  using tri::ch08::bands_for;
  CHECK(bands_for(512, 2).rows == 64);
  CHECK(bands_for(512, 4).rows == 32);
  CHECK(bands_for(512, 8).rows == 16);
  CHECK(bands_for(512, 64).rows == 16);
  CHECK(bands_for(4096, 2).rows == 64);
  CHECK(bands_for(45, 2).rows == 16);
  CHECK(bands_for(200, 3).rows == 16);  // 200 / 12 = 16.7, a multiple of 8 below
  const tri::ch08::Bands two{64, 2};
  CHECK(two.owner(0) == 0);
  CHECK(two.owner(63) == 0);
  CHECK(two.owner(64) == 1);
  CHECK(two.owner(128) == 0);
  CHECK(tri::ch08::Bands{16, 3}.owner(47) == 2);
}

TEST_CASE("The threaded batch equals the serial one pixel for pixel, colours and write counts",
          "[08_fast_exact][step7]") {
  for (const auto& [width, height] : {std::pair{50, 45}, std::pair{64, 64}, std::pair{13, 100}}) {
    const auto scene = overlapping_scene(static_cast<std::uint64_t>(width * height), 400, 48);
    for (const bool counting : {true, false}) {
      const Canvas serial = drawn_on(width, height, counting, [&](Canvas& canvas) {
        tri::ch08::draw_batch_hybrid(canvas, scene);
      });
      for (const int threads : {1, 2, 3, 4, 7, 100}) {
        INFO(width << "x" << height << ", " << threads << " threads, counting " << counting);
        const Canvas threaded = drawn_on(width, height, counting, [&](Canvas& canvas) {
          tri::ch08::draw_batch_on_threads(canvas, scene, threads);
        });
        CHECK(threaded.outside_writes() == 0);
        CHECK(same_canvas(threaded, serial));
      }
      CHECK(same_canvas(
          drawn_on(width, height, counting,
                   [&](Canvas& canvas) { tri::ch08::draw_batch_threaded(canvas, scene); }),
          serial));
    }
  }
}

TEST_CASE("Each thread writes only the rows of its own bands, and together they write all",
          "[08_fast_exact][step7]") {
  const auto scene = overlapping_scene(9, 300, 60);
  const Canvas serial =
      drawn_on(60, 70, true, [&](Canvas& canvas) { tri::ch08::draw_batch_hybrid(canvas, scene); });
  for (const int threads : {2, 3}) {
    std::vector<std::uint32_t> total(serial.write_counts().size(), 0);
    for (int thread = 0; thread < threads; ++thread) {
      const Canvas part = drawn_on(60, 70, true, [&](Canvas& canvas) {
        tri::ch08::draw_bands_of_thread(canvas, scene, thread, threads);
      });
      for (int y = 0; y < 70; ++y) {
        for (int x = 0; x < 60; ++x) {
          if (part.write_count(x, y) > 0) {
            REQUIRE(tri::ch08::bands_for(70, threads).owner(y) == thread);
          }
          total[static_cast<std::size_t>(y) * 60 + static_cast<std::size_t>(x)] +=
              part.write_count(x, y);
        }
      }
    }
    CHECK(std::equal(total.begin(), total.end(), serial.write_counts().begin()));
  }
}
