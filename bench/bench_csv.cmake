# bench_csv.cmake — included by the bench.*_csv ctest scripts: runs
# `${FLIPFLOP} bench ARGS...`, fails the test when it exits non-zero or its
# first line is not HEADER, and sets ROWS_VAR to the other lines (a list).
function(flipflop_bench_rows rows_var header)
  execute_process(COMMAND ${FLIPFLOP} bench ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "flipflop bench ${ARGN} failed (${rc}): ${err}")
  endif()
  string(REGEX REPLACE "\n$" "" out "${out}")
  string(REPLACE "\n" ";" lines "${out}")
  list(GET lines 0 first)
  if(NOT first STREQUAL header)
    message(FATAL_ERROR "flipflop bench ${ARGN}: header is '${first}', expected '${header}'")
  endif()
  list(REMOVE_AT lines 0)
  set(${rows_var} "${lines}" PARENT_SCOPE)
endfunction()
