// The conformance program's entry point; everything else lives in the library so tests and a
// chapter can run it.
#include <iostream>

#include "chapters/11_your_rasterizer/conformance_app.hpp"

int main(int argc, char** argv) {
  return tri::conformance::run_conformance(argc, argv, std::cout, std::cerr);
}
