# Runs the Python E2E reference: its selftest, and the vectors it gives now must equal the
# checked-in e2e_vectors.inc and crc_vectors.inc (same generator arguments as their first line).
execute_process(COMMAND /usr/bin/python3 ${SCRIPT} selftest RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "e2e_reference.py selftest failed")
endif()
foreach(pair "vectors;e2e_vectors.inc" "crc-vectors;crc_vectors.inc")
  list(GET pair 0 mode)
  list(GET pair 1 file)
  file(STRINGS ${DIR}/${file} first LIMIT_COUNT 1)
  string(REGEX MATCH "${mode} ([0-9]+) ([0-9]+)" _ "${first}")
  execute_process(COMMAND /usr/bin/python3 ${SCRIPT} ${mode} ${CMAKE_MATCH_1} ${CMAKE_MATCH_2}
                  OUTPUT_VARIABLE now RESULT_VARIABLE rc)
  file(READ ${DIR}/${file} stored)
  if(NOT rc EQUAL 0 OR NOT now STREQUAL stored)
    message(FATAL_ERROR "${file} differs from what e2e_reference.py ${mode} gives now")
  endif()
endforeach()
