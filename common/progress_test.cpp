#include "common/progress.hpp"

#include <catch2/catch.hpp>

#include <regex>
#include <sstream>
#include <thread>

#include "common/cli.hpp"

namespace tri {

TEST_CASE("Durations read as seconds, minutes or hours", "[common][progress]") {
  CHECK(human_duration(0.4) == "0 s");
  CHECK(human_duration(12.4) == "12 s");
  CHECK(human_duration(600) == "10 min");
  CHECK(human_duration(3 * 3600 + 720) == "3.2 h");
}

TEST_CASE("A run estimated beyond the limit is refused unless forced, a shorter one is not",
          "[common][progress]") {
  CHECK_NOTHROW(refuse_absurd_run(60, "drawing", false));
  CHECK_THROWS_AS(refuse_absurd_run(3600, "drawing 10 frames", false), UsageError);
  CHECK_THROWS_WITH(refuse_absurd_run(3600, "drawing 10 frames", false),
                    "drawing 10 frames would take about 60 min, more than 10 min; add --force to "
                    "run it anyway");
  CHECK_NOTHROW(refuse_absurd_run(3600, "drawing", true));
}

TEST_CASE("Progress is silent during the quiet period, then reports the share done and time left",
          "[common][progress]") {
  std::ostringstream err;
  Progress quiet("raster", 100, err, std::chrono::hours(1));
  quiet.advance(50);
  CHECK(err.str().empty());

  Progress progress("raster", 100, err, std::chrono::milliseconds(0), std::chrono::hours(1));
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  progress.advance(25);
  progress.advance(50);  // within the interval: no second line
  CHECK(progress.lines_printed() == 1);
  CHECK(std::regex_match(err.str(), std::regex("raster: 25% done, about [0-9]+ s left\n")));
}

}  // namespace tri
