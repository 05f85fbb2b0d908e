// Chapter 11: your rasterizer. Write the body of your_fill, then grade it:
//   cmake --build --preset release --target 11_your_rasterizer
//   ./build/release/chapters/11_your_rasterizer/11_your_rasterizer --grade out/mine
#include "chapters/11_your_rasterizer/your_fill.hpp"

namespace tri::ch11 {

// [listing your_fill]
void your_fill(Canvas& canvas, const Triangle& triangle, Color color) {
  // Your code here. The tools of the book are yours: the edge functions of chapter 05, the
  // top-left rule of chapter 07 and its exact integer arithmetic, the spans of chapter 08.
  // Start with the bounding box of the triangle, cut to the canvas, and test every centre.
  (void)canvas;
  (void)triangle;
  (void)color;
}
// [/listing]

}  // namespace tri::ch11
