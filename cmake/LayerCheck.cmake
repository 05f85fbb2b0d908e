# The layers of docs/DESIGN.md section 2, checked: tutorial_record_layer_links() writes, at
# configure time, what each chapter target links; the test "conventions/every chapter depends
# only on earlier layers" runs check_layers.cmake on that file and on the sources.

# tutorial_record_layer_links(<file>): one line "target: linked;linked;..." per chapter target
# (the library chNN_*, the executable NN_* and the test executable chNN_*_tests) of the
# algorithm chapters, 01 to 09 (chapter 10, the report, sits above measure/).
function(tutorial_record_layer_links file)
  set(lines "")
  foreach(number 01 02 03 04 05 06 07 08 09)
    file(GLOB folder LIST_DIRECTORIES true "${PROJECT_SOURCE_DIR}/chapters/${number}_*")
    get_filename_component(name "${folder}" NAME)
    foreach(target ch${name} ${name} ch${name}_tests)
      if(TARGET ${target})
        get_target_property(links ${target} LINK_LIBRARIES)
        get_target_property(interface ${target} INTERFACE_LINK_LIBRARIES)
        string(APPEND lines "${number} ${target}: ${links};${interface}\n")
      endif()
    endforeach()
  endforeach()
  file(WRITE "${file}" "${lines}")
endfunction()
