# cmake -DLINKS=<file> -DROOT=<repository> -P check_layers.cmake
# The layers of docs/DESIGN.md section 2: common/ <- chapters 01-09 (each on earlier ones only)
# <- measure/ <- chapter 10 and after, tools/, tests/, fuzz/. Fails when
# - a chapter 01-09 target links anything but common/, the test support, outside libraries and
#   its own or earlier chapters;
# - common/ includes anything outside common/ (its tests may use tests/support);
# - a chapter includes a later chapter, or a chapter 01-09 includes measure/, tools/, tests/ or
#   fuzz/ (its *_test.cpp files and the test-only headers they include may use tests/support);
# - measure/ includes chapter 10 or later, tools/, tests/ or fuzz/;
# - chapter 10 or later includes tools/, tests/ (but tests/support in tests) or fuzz/.
cmake_minimum_required(VERSION 3.22)
set(problems "")
set(allowed common tutorial_options test_support glm::glm stb::stb Threads::Threads
            Catch2::Catch2 Catch2::Catch2WithMain)
file(STRINGS "${LINKS}" lines)
foreach(line IN LISTS lines)
  string(REGEX MATCH "^([0-9][0-9]) ([^:]+): (.*)$" _ "${line}")
  set(number ${CMAKE_MATCH_1})
  set(target ${CMAKE_MATCH_2})
  set(links ${CMAKE_MATCH_3})
  string(REGEX REPLACE "\\$<LINK_ONLY:([^>]*)>" "\\1" links "${links}")
  foreach(link IN LISTS links)
    if(link STREQUAL "" OR link MATCHES "NOTFOUND$" OR link IN_LIST allowed)
      continue()
    endif()
    if(link MATCHES "^ch([0-9][0-9])_" AND CMAKE_MATCH_1 LESS_EQUAL number)
      continue()
    endif()
    list(APPEND problems "${target} links ${link}")
  endforeach()
endforeach()

file(GLOB_RECURSE sources "${ROOT}/common/*.cpp" "${ROOT}/common/*.hpp"
     "${ROOT}/chapters/*.cpp" "${ROOT}/chapters/*.hpp"
     "${ROOT}/measure/*.cpp" "${ROOT}/measure/*.hpp")

# Test-only headers are those that include tests/support; only *_test.cpp files may include
# them or tests/support itself.
set(test_headers "")
foreach(source IN LISTS sources)
  file(STRINGS "${source}" support REGEX "^#include \"tests/support/")
  if(support AND source MATCHES "\\.hpp$")
    file(RELATIVE_PATH relative "${ROOT}" "${source}")
    list(APPEND test_headers "${relative}")
  endif()
endforeach()

foreach(source IN LISTS sources)
  file(RELATIVE_PATH relative "${ROOT}" "${source}")
  set(is_test FALSE)
  if(relative MATCHES "_test\\.cpp$")
    set(is_test TRUE)
  endif()
  # The layer of the including file: 0 common, 1-9 the algorithm chapters, 50 measure, 100 + N
  # for chapter N from 10 on.
  if(relative MATCHES "^common/")
    set(layer 0)
  elseif(relative MATCHES "^measure/")
    set(layer 50)
  elseif(relative MATCHES "^chapters/([0-9][0-9])_")
    math(EXPR layer "${CMAKE_MATCH_1}")
    if(layer GREATER_EQUAL 10)
      math(EXPR layer "100 + ${layer}")
    endif()
  else()
    continue()
  endif()
  file(STRINGS "${source}" includes REGEX "^#include \"")
  foreach(include IN LISTS includes)
    string(REGEX MATCH "\"([^\"]+)\"" _ "${include}")
    set(path ${CMAKE_MATCH_1})
    if(path MATCHES "^tests/support/" OR path IN_LIST test_headers)
      if(NOT is_test AND relative MATCHES "\\.cpp$")
        list(APPEND problems "${relative} (not a test) includes the test-only ${path}")
      endif()
      continue()
    endif()
    if(path MATCHES "^(tools|tests|fuzz|docs)/")
      list(APPEND problems "${relative} includes ${path}")
    elseif(path MATCHES "^common/")
    elseif(path MATCHES "^measure/")
      if(layer LESS 50)
        list(APPEND problems "${relative} includes the later layer's ${path}")
      endif()
    elseif(path MATCHES "^chapters/([0-9][0-9])_")
      math(EXPR included "${CMAKE_MATCH_1}")
      if(included GREATER_EQUAL 10)
        math(EXPR included "100 + ${included}")
      endif()
      if(included GREATER layer)
        list(APPEND problems "${relative} includes the later layer's ${path}")
      endif()
    endif()
  endforeach()
endforeach()

if(problems)
  list(JOIN problems "\n  " text)
  message(FATAL_ERROR "Layer violations (docs/DESIGN.md section 2):\n  ${text}")
endif()
message(STATUS "common/ <- chapters 01-09 <- measure/ <- chapters 10 and after: no file or "
               "target depends on a later layer")
