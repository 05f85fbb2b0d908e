# Helpers shared by every folder: warning flags, sanitizers, chapter executables and tests.

add_library(tutorial_options INTERFACE)
target_compile_options(tutorial_options INTERFACE
  $<$<CXX_COMPILER_ID:GNU,Clang>:-Wall -Wextra -Wpedantic>
  $<$<AND:$<BOOL:${TUTORIAL_WARNINGS_AS_ERRORS}>,$<CXX_COMPILER_ID:GNU,Clang>>:-Werror>
  # Every product rounded on its own, as written: a fused multiply-add would change which pixels
  # the float algorithms get wrong, and differ between compilers and -march settings.
  $<$<CXX_COMPILER_ID:GNU,Clang>:-ffp-contract=off>)
# GCC 12 reports a false -Wrestrict inside libstdc++ on plain std::string concatenation at -O2
# (GCC bug 105329); nothing in our code can fix it, so that one diagnostic is off for GCC 12.
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_GREATER_EQUAL 12
   AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
  target_compile_options(tutorial_options INTERFACE -Wno-restrict)
endif()
# Opt-in: compile everything for the host's own instructions (the result runs only on processors
# like the one that built it), every copy of chapter 08's dispatched loops included. Portable
# x86-64 (SSE2) by default, where those loops' wider copies are chosen at run time.
option(TUTORIAL_NATIVE "Compile every target with -march=native" OFF)
if(TUTORIAL_NATIVE)
  target_compile_options(tutorial_options INTERFACE $<$<CXX_COMPILER_ID:GNU,Clang>:-march=native>)
endif()
if(TUTORIAL_SANITIZE)
  # A float-to-integer conversion of a value out of the integer's range is undefined behaviour
  # that GCC's -fsanitize=undefined does not check (Clang's does): asked for by name where known.
  include(CheckCXXSourceCompiles)
  set(CMAKE_REQUIRED_FLAGS -fsanitize=float-cast-overflow)
  set(CMAKE_REQUIRED_LINK_OPTIONS -fsanitize=float-cast-overflow)
  check_cxx_source_compiles("int main() { return 0; }" TUTORIAL_HAS_FLOAT_CAST_OVERFLOW_CHECK)
  unset(CMAKE_REQUIRED_FLAGS)
  unset(CMAKE_REQUIRED_LINK_OPTIONS)
  set(sanitizers address,undefined)
  if(TUTORIAL_HAS_FLOAT_CAST_OVERFLOW_CHECK)
    set(sanitizers address,undefined,float-cast-overflow)
  endif()
  target_compile_options(tutorial_options INTERFACE
    -fsanitize=${sanitizers} -fno-sanitize-recover=all -fno-omit-frame-pointer)
  target_link_options(tutorial_options INTERFACE -fsanitize=${sanitizers})
endif()

set(TUTORIAL_FIGURE_COMMANDS "" CACHE INTERNAL "")

set(TUTORIAL_GOLDEN_PROGRAMS "" CACHE INTERNAL "")

# tutorial_figure_program(<target> [TIMED])
# Registers a program that renders figures with --out DIR: the 'figures' target runs it, and,
# unless its figures come from a timed run (TIMED), the golden-figure tests compare what it
# renders with the copies committed in docs/figures.
function(tutorial_figure_program target)
  cmake_parse_arguments(ARG "TIMED" "" "" ${ARGN})
  set(TUTORIAL_FIGURE_COMMANDS ${TUTORIAL_FIGURE_COMMANDS}
      COMMAND $<TARGET_FILE:${target}> --out "${TUTORIAL_FIGURES_DIR}"
      CACHE INTERNAL "")
  if(NOT ARG_TIMED)
    set(TUTORIAL_GOLDEN_PROGRAMS ${TUTORIAL_GOLDEN_PROGRAMS} ${target} CACHE INTERNAL "")
  endif()
endfunction()

# tutorial_chapter_executable(<nn_name> [TIMED_FIGURES] <libraries>...)
# Builds the chapter's executable <nn_name> from main.cpp and registers it as a figure program
# (see tutorial_figure_program) so that the run command renders its figures.
function(tutorial_chapter_executable chapter)
  cmake_parse_arguments(ARG "TIMED_FIGURES" "" "" ${ARGN})
  add_executable(${chapter} main.cpp)
  target_link_libraries(${chapter} PRIVATE ${ARG_UNPARSED_ARGUMENTS} tutorial_options)
  if(ARG_TIMED_FIGURES)
    tutorial_figure_program(${chapter} TIMED)
  else()
    tutorial_figure_program(${chapter})
  endif()
endfunction()

# tutorial_tests(<target> <test prefix> SOURCES... LIBRARIES... [LABELS...])
# One Catch2 executable per folder; every TEST_CASE becomes a CTest test named
# "<prefix>/<test name>", so 'ctest -R 01_lines' runs one chapter alone.
function(tutorial_tests target prefix)
  cmake_parse_arguments(ARG "" "" "SOURCES;LIBRARIES;LABELS" ${ARGN})
  add_executable(${target} ${ARG_SOURCES})
  target_link_libraries(${target} PRIVATE ${ARG_LIBRARIES} test_support Catch2::Catch2WithMain
                        tutorial_options)
  set(properties TIMEOUT 600)
  if(ARG_LABELS)
    list(APPEND properties LABELS "${ARG_LABELS}")
  endif()
  # The test-name check (tests/conventions) reads every folder's sources with their prefix.
  set(sources --prefix ${prefix})
  foreach(source IN LISTS ARG_SOURCES)
    list(APPEND sources "${CMAKE_CURRENT_SOURCE_DIR}/${source}")
  endforeach()
  set_property(GLOBAL APPEND PROPERTY TUTORIAL_TEST_SOURCES ${sources})
  catch_discover_tests(${target} TEST_PREFIX "${prefix}/"
                       WORKING_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}"
                       PROPERTIES ${properties})
endfunction()
