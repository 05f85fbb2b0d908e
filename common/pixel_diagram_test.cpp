// The pixel diagram writer: where things land in the SVG, and that the output is stable.
#include "common/pixel_diagram.hpp"

#include <catch2/catch.hpp>

#include <string>

#include "tests/support/text.hpp"

namespace {

using tri::PixelDiagram;
using tri::testing::occurrences;
namespace dc = tri::diagram_colors;

}  // namespace

TEST_CASE("A pixel diagram puts pixel (i, j) in the cell of column i, counted from the top row",
          "[common][pixel_diagram]") {
  // Pixels 0..3 by 0..2 at 10 units per cell: the grid starts at (34, 34); y = 2 is the top row.
  PixelDiagram diagram({0, 0}, {3, 2}, "t", 10);
  diagram.fill({1, 2}, dc::orange);
  diagram.fill({3, 0}, dc::blue);
  const std::string svg = diagram.svg();
  CHECK(svg.find("<rect x=\"44\" y=\"34\" width=\"10\" height=\"10\" fill=\"#e69f00\"/>") !=
        std::string::npos);
  CHECK(svg.find("<rect x=\"64\" y=\"54\" width=\"10\" height=\"10\" fill=\"#0072b2\"/>") !=
        std::string::npos);
}

TEST_CASE("A pixel diagram merges a run of equal pixels along a row into one rectangle",
          "[common][pixel_diagram]") {
  PixelDiagram diagram({0, 0}, {9, 0}, "t", 10);
  for (int x = 2; x <= 6; ++x) diagram.fill({x, 0}, dc::bluish_green);
  const std::string svg = diagram.svg();
  CHECK(occurrences(svg, "fill=\"#009e73\"") == 1);
  CHECK(svg.find("width=\"50\" height=\"10\" fill=\"#009e73\"") != std::string::npos);
}

TEST_CASE("A pixel diagram draws the ideal geometry at exact pixel coordinates, y up",
          "[common][pixel_diagram]") {
  // The centre of pixel (0, 0) in a 2x2 grid of 20-unit cells is at (34 + 10, 34 + 20 + 10).
  PixelDiagram diagram({0, 0}, {1, 1}, "t", 20);
  diagram.line({0, 0}, {1, 0.5}, dc::black, 2);
  const std::string svg = diagram.svg();
  CHECK(svg.find("x1=\"44\" y1=\"64\" x2=\"64\" y2=\"54\"") != std::string::npos);
}

TEST_CASE("A pixel diagram labels a vertex with its exact coordinates", "[common][pixel_diagram]") {
  PixelDiagram diagram({0, 0}, {4, 4}, "t");
  diagram.vertex({2.5, -0.125}, "A");
  diagram.vertex({1e7, 3}, "B");
  const std::string svg = diagram.svg();
  CHECK(svg.find(">A (2.5, -0.125)</text>") != std::string::npos);
  CHECK(svg.find(">B (1e+07, 3)</text>") != std::string::npos);
}

TEST_CASE("A pixel diagram has its title, pixel numbers and every legend entry inside the image",
          "[common][pixel_diagram]") {
  PixelDiagram diagram({10, 20}, {12, 21}, "Ties & <edges>", 24);
  diagram.legend_fill("covered", dc::covered);
  diagram.legend_mark("centre on an edge", tri::PixelMark::ring);
  diagram.legend_line("ideal edge", dc::blue, true);
  diagram.legend_note("one note");
  const std::string svg = diagram.svg();
  CHECK(svg.find(">Ties &amp; &lt;edges&gt;</text>") != std::string::npos);
  for (const char* tick : {">10</text>", ">11</text>", ">12</text>", ">20</text>", ">21</text>"}) {
    CHECK(svg.find(tick) != std::string::npos);
  }
  for (const char* entry :
       {">covered</text>", ">centre on an edge</text>", ">ideal edge</text>", ">one note</text>"}) {
    CHECK(svg.find(entry) != std::string::npos);
  }
  CHECK(svg.find("stroke-dasharray") != std::string::npos);
}

TEST_CASE("A legend dot is drawn beside its text with the colour and radius asked for",
          "[common][pixel_diagram]") {
  PixelDiagram diagram({0, 0}, {1, 1}, "t", 24);
  diagram.show_centres(false);
  const std::string without = diagram.svg();
  diagram.legend_point("a sample inside", dc::blue, 3);
  const std::string svg = diagram.svg();
  CHECK(svg.find(">a sample inside</text>") != std::string::npos);
  CHECK(svg.find("r=\"3\" fill=\"#0072b2\"") != std::string::npos);
  CHECK(without.find("<circle") == std::string::npos);
}

TEST_CASE("A pixel diagram shows pixel centres on zoomed grids and can hide them",
          "[common][pixel_diagram]") {
  PixelDiagram zoomed({0, 0}, {3, 3}, "t", 24);
  CHECK(zoomed.svg().find("centres") != std::string::npos);
  zoomed.show_centres(false);
  CHECK(zoomed.svg().find("centres") == std::string::npos);
  PixelDiagram dense({0, 0}, {3, 3}, "t", 3);
  CHECK(dense.svg().find("centres") == std::string::npos);
}

TEST_CASE("A pixel diagram ignores pixels and marks outside its range", "[common][pixel_diagram]") {
  PixelDiagram diagram({0, 0}, {1, 1}, "t", 10);
  const std::string before = diagram.svg();
  diagram.fill({2, 0}, dc::orange);
  diagram.fill({0, -1}, dc::orange);
  diagram.mark({5, 5}, tri::PixelMark::cross);
  diagram.pixel_text({-1, 0}, "2");
  CHECK(diagram.svg() == before);
}

TEST_CASE("A pixel diagram copies a canvas's colours except the skipped background",
          "[common][pixel_diagram]") {
  tri::Canvas canvas(3, 1, tri::colors::black);
  canvas.put_pixel(1, 0, tri::colors::yellow);
  PixelDiagram diagram({5, 5}, {7, 5}, "t", 10);
  diagram.fill_from(canvas, tri::colors::black, {5, 5});
  const std::string svg = diagram.svg();
  CHECK(occurrences(svg, "fill=\"#ffff00\"") == 1);
  CHECK(svg.find("<rect x=\"44\" y=\"34\" width=\"10\" height=\"10\" fill=\"#ffff00\"/>") !=
        std::string::npos);
  CHECK(occurrences(svg, "fill=\"#000000\"/>") == 0);
}

TEST_CASE("Side-by-side diagrams keep their patterns apart", "[common][pixel_diagram]") {
  const std::vector<PixelDiagram> panels = {PixelDiagram({0, 0}, {2, 2}, "left"),
                                            PixelDiagram({0, 0}, {2, 2}, "right")};
  const std::string svg = tri::side_by_side(panels, "both");
  CHECK(svg.find("id=\"p0-grid\"") != std::string::npos);
  CHECK(svg.find("id=\"p1-grid\"") != std::string::npos);
  CHECK(svg.find(">both</text>") != std::string::npos);
}

TEST_CASE("A pixel diagram is the same bytes every time and refuses an empty range",
          "[common][pixel_diagram]") {
  const auto draw = [] {
    PixelDiagram diagram({-2, -2}, {2, 2}, "t");
    diagram.triangle({-1.5, -1}, {1.25, 0}, {0, 1.75}, dc::blue);
    diagram.mark({0, 0}, tri::PixelMark::hatch, dc::vermillion);
    return diagram.svg();
  };
  CHECK(draw() == draw());
  CHECK_THROWS_AS(PixelDiagram({1, 0}, {0, 0}, "t"), std::invalid_argument);
  CHECK_THROWS_AS(PixelDiagram({0, 0}, {1, 1}, "t", 0.5), std::invalid_argument);
}

TEST_CASE("A pixel diagram cuts the ideal geometry to its pixels", "[common][pixel_diagram]") {
  // Grid of pixels 0..1 x 0..1 at 20 units: the box [-0.5, 1.5]^2 spans SVG x 34..74, y 34..74.
  PixelDiagram diagram({0, 0}, {1, 1}, "t", 20);
  diagram.line({-10.5, 0.5}, {100, 0.5}, dc::black);  // crosses the grid between its rows
  diagram.line({5, 5}, {9, 9}, dc::black);            // misses it entirely
  const std::string svg = diagram.svg();
  CHECK(svg.find("x1=\"34\" y1=\"54\" x2=\"74\" y2=\"54\"") != std::string::npos);
  CHECK(occurrences(svg, "<line") == 1);
}

TEST_CASE("clip_segment keeps the part of a segment inside a box", "[common][pixel_diagram]") {
  const auto inside = tri::clip_segment({-1, 1}, {3, 1}, {0, 0}, {2, 2});
  REQUIRE(inside);
  CHECK((*inside)[0] == glm::dvec2(0, 1));
  CHECK((*inside)[1] == glm::dvec2(2, 1));
  CHECK_FALSE(tri::clip_segment({-1, 3}, {3, 3}, {0, 0}, {2, 2}));
  const auto whole = tri::clip_segment({0.5, 0.5}, {1, 1.5}, {0, 0}, {2, 2});
  REQUIRE(whole);
  CHECK((*whole)[1] == glm::dvec2(1, 1.5));
}

TEST_CASE("clip_to_pixels keeps the part of a segment over the squares of the chosen pixels",
          "[common][pixel_diagram]") {
  const auto cut = tri::clip_to_pixels({4.5, 4.5}, {24.5, 4.5}, {0, 0}, {9, 9});
  REQUIRE(cut);
  CHECK((*cut)[0] == glm::dvec2(4.5, 4.5));
  CHECK((*cut)[1] == glm::dvec2(9.5, 4.5));
  const auto both = tri::clip_to_pixels({-10.5, -10.5}, {20.5, 20.5}, {0, 0}, {9, 9});
  REQUIRE(both);
  CHECK((*both)[0] == glm::dvec2(-0.5, -0.5));
  CHECK((*both)[1] == glm::dvec2(9.5, 9.5));
  CHECK_FALSE(tri::clip_to_pixels({20, 0}, {20, 9}, {0, 0}, {9, 9}));
  CHECK_FALSE(tri::clip_to_pixels({-5, 0}, {0, -5}, {0, 0}, {9, 9}));
}

TEST_CASE("A pixel diagram frames a region along the outer border of its pixels",
          "[common][pixel_diagram]") {
  // Pixels 1..2 x 0..1 of a 4x2 grid at 10 units: the border runs from x 44 to 64, y 34 to 54.
  PixelDiagram diagram({0, 0}, {3, 1}, "t", 10);
  diagram.frame({1, 0}, {2, 1}, dc::black);
  const std::string svg = diagram.svg();
  CHECK(occurrences(svg, "<line") == 4);
  CHECK(svg.find("x1=\"44\" y1=\"54\" x2=\"64\" y2=\"54\"") != std::string::npos);
  CHECK(svg.find("x1=\"64\" y1=\"54\" x2=\"64\" y2=\"34\"") != std::string::npos);
  CHECK(svg.find("x1=\"64\" y1=\"34\" x2=\"44\" y2=\"34\"") != std::string::npos);
  CHECK(svg.find("x1=\"44\" y1=\"34\" x2=\"44\" y2=\"54\"") != std::string::npos);
}
