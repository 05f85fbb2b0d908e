# Runs COMMAND (a ;-list) in a new empty folder FOLDER and fails when the command failed or left
# anything there: tests write into scratch folders, never into their working directory.
file(REMOVE_RECURSE "${FOLDER}")
file(MAKE_DIRECTORY "${FOLDER}")
execute_process(COMMAND ${COMMAND} WORKING_DIRECTORY "${FOLDER}" RESULT_VARIABLE result
                OUTPUT_QUIET)
file(GLOB left LIST_DIRECTORIES true "${FOLDER}/*" "${FOLDER}/.*")
file(REMOVE_RECURSE "${FOLDER}")
if(NOT result EQUAL 0)
  message(FATAL_ERROR "${COMMAND} failed: ${result}")
endif()
if(left)
  message(FATAL_ERROR "${COMMAND} wrote into its working directory: ${left}")
endif()
