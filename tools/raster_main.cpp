// The raster tool's entry point; everything else lives in raster_app.cpp so tests can run it.
#include <iostream>

#include "tools/raster_app.hpp"

int main(int argc, char** argv) {
  return tri::run_raster(argc, argv, std::cout, std::cerr);
}
