# Finds the tutorial's four dependencies through CMake's usual ways. A missing one stops
# configuration with the name of the Debian package that provides it.

function(tutorial_require found what package)
  if(NOT ${found})
    message(FATAL_ERROR
      "${what} was not found. On Debian install it with: sudo apt-get install ${package}\n"
      "(or run ./tutorial.sh, which installs what is missing)")
  endif()
endfunction()

find_package(glm CONFIG QUIET)
tutorial_require(glm_FOUND "GLM (OpenGL Mathematics)" libglm-dev)

# stb has no CMake package: Debian's libstb-dev ships the headers under /usr/include/stb and a
# compiled libstb, so we look both up and wrap them in an imported target.
find_path(STB_INCLUDE_DIR stb_image_write.h PATH_SUFFIXES stb)
find_library(STB_LIBRARY NAMES stb)
if(STB_INCLUDE_DIR AND STB_LIBRARY)
  set(STB_FOUND TRUE)
endif()
tutorial_require(STB_FOUND "stb_image_write (headers and libstb)" libstb-dev)
if(NOT TARGET stb::stb)
  add_library(stb::stb UNKNOWN IMPORTED)
  set_target_properties(stb::stb PROPERTIES
    IMPORTED_LOCATION "${STB_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${STB_INCLUDE_DIR}")
endif()

find_package(Catch2 2 CONFIG QUIET)
tutorial_require(Catch2_FOUND "Catch2 v2" catch2)
include(Catch)

if(TUTORIAL_BUILD_DOCS)
  find_package(Doxygen QUIET)
  tutorial_require(DOXYGEN_FOUND "Doxygen" doxygen)
endif()
