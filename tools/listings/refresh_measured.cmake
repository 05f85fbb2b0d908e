# The measured_numbers target's steps: chapter 10's report in its quick setting writes the book's
# snapshot and its plots, the plots the READMEs show are copied from that same run, the listings
# tool refills every measured number in the Markdown from the snapshot, and chapter 10's figures
# drawn from the snapshot are drawn again.
# Called as cmake -DROOT=... -DREPORT=... -DLISTINGS=... -DFIGURES=... -DOUT=... [-DNOTE=...]
# -P this file.
execute_process(COMMAND git -C "${ROOT}" describe --always --dirty --abbrev=12
  OUTPUT_VARIABLE commit OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE git_result ERROR_QUIET)
if(NOT git_result EQUAL 0)
  set(commit unknown)
endif()
execute_process(COMMAND "${REPORT}" --out "${OUT}"
    --snapshot "${ROOT}/docs/measurements/report_quick.csv" --commit "${commit}" --note "${NOTE}"
  COMMAND_ERROR_IS_FATAL ANY)
execute_process(COMMAND "${LISTINGS}" --update "${ROOT}" COMMAND_ERROR_IS_FATAL ANY)
foreach(plot 10_speed_vs_error 10_coverage_speed_vs_error 10_scaling_triangles 10_scaling_canvas)
  file(COPY_FILE "${OUT}/${plot}.svg" "${ROOT}/docs/figures/${plot}.svg")
endforeach()
execute_process(COMMAND "${FIGURES}" --out "${ROOT}/docs/figures" COMMAND_ERROR_IS_FATAL ANY)
