# gzip -9n INPUT > OUTPUT (run as `cmake -P`): compressed the way Debian asks, without the file's
# name or time stamp inside, so the package is reproducible.
execute_process(COMMAND gzip -9nc "${INPUT}" OUTPUT_FILE "${OUTPUT}" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "gzip failed for ${INPUT}")
endif()
