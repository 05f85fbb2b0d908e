# cmake -DSCRATCH=<empty folder> -DCHECK=<check_layers.cmake> -P check_layers_test.cmake
# Runs the layer check on small made-up trees: one that keeps every layer passes, and each tree
# with one dependency on a later layer fails, naming the file or target.
cmake_minimum_required(VERSION 3.22)

# write_tree(<name>): a tree in which every layer depends only on earlier ones.
function(write_tree root)
  file(REMOVE_RECURSE "${root}")
  file(WRITE "${root}/common/canvas.hpp" "#include \"common/color.hpp\"\n")
  file(WRITE "${root}/chapters/03_fill/fill.cpp" "#include \"chapters/01_lines/line.hpp\"\n")
  file(WRITE "${root}/chapters/03_fill/fill_test.cpp" "#include \"tests/support/pixels.hpp\"\n")
  file(WRITE "${root}/chapters/09_area/area.cpp" "#include \"chapters/08_fast/spans.hpp\"\n")
  file(WRITE "${root}/measure/registry.cpp" "#include \"chapters/09_area/area.hpp\"\n")
  file(WRITE "${root}/chapters/10_report/report.cpp"
       "#include \"measure/registry.hpp\"\n#include \"chapters/09_area/area.hpp\"\n")
  file(WRITE "${root}/links.txt" "03 ch03_fill: common;ch01_lines\n09 ch09_area: ch08_fast\n")
endfunction()

# expect(<case> <expected regex or PASS>)
function(expect case expected)
  execute_process(COMMAND "${CMAKE_COMMAND}" -DLINKS=${root}/links.txt -DROOT=${root} -P "${CHECK}"
                  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(expected STREQUAL "PASS")
    if(NOT status EQUAL 0)
      message(FATAL_ERROR "${case}: the layer check failed on a tree without violations:\n${err}")
    endif()
  elseif(status EQUAL 0 OR NOT err MATCHES "${expected}")
    message(FATAL_ERROR "${case}: expected a failure matching '${expected}', got status "
                        "${status}:\n${out}${err}")
  endif()
endfunction()

set(root "${SCRATCH}/tree")
write_tree("${root}")
expect("a tree that keeps the layers" PASS)

# Each case: one file appended to the good tree, and the message that names it.
set(cases
  "common/figures.cpp|#include \"chapters/01_lines/line.hpp\"|common/figures.cpp includes the later"
  "common/scene.cpp|#include \"measure/registry.hpp\"|common/scene.cpp includes the later"
  "chapters/03_fill/steps.cpp|#include \"chapters/05_edge/edge.hpp\"|03_fill/steps.cpp includes the later"
  "chapters/09_area/cells.cpp|#include \"chapters/10_report/report.hpp\"|09_area/cells.cpp includes the later"
  "chapters/08_fast/bench.cpp|#include \"measure/timing.hpp\"|08_fast/bench.cpp includes the later"
  "chapters/08_fast/spans.cpp|#include \"tests/support/pixels.hpp\"|spans.cpp \\(not a test\\)"
  "measure/suites.cpp|#include \"chapters/10_report/suites.hpp\"|measure/suites.cpp includes the later"
  "measure/timing.cpp|#include \"tools/raster_app.hpp\"|measure/timing.cpp includes tools/"
  "chapters/10_report/main.cpp|#include \"tools/raster_app.hpp\"|10_report/main.cpp includes tools/")
foreach(case IN LISTS cases)
  string(REPLACE "|" ";" parts "${case}")
  list(GET parts 0 file)
  list(GET parts 1 line)
  list(GET parts 2 expected)
  write_tree("${root}")
  file(WRITE "${root}/${file}" "${line}\n")
  expect("${file}" "${expected}")
endforeach()

# A chapter target that links a later chapter's library.
write_tree("${root}")
file(APPEND "${root}/links.txt" "05 ch05_edge: common;ch07_exact\n")
expect("ch05_edge links ch07_exact" "ch05_edge links ch07_exact")
file(REMOVE_RECURSE "${root}")
message(STATUS "The layer check passes the layered tree and fails each dependency on a later layer")
