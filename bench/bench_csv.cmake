# bench_csv.cmake — included by the bench.*_csv ctest scripts: runs
# `${FLIPFLOP} bench ARGS...`, fails the test when it exits non-zero, when it
# does not start with the two comment lines (`# flipflop bench ARGS`,
# `# machine: CPU model, processors, caches, load average`) or when the next
# line is not HEADER, and sets ROWS_VAR to the other lines (a list).
function(flipflop_bench_rows rows_var header)
  execute_process(COMMAND ${FLIPFLOP} bench ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "flipflop bench ${ARGN} failed (${rc}): ${err}")
  endif()
  string(REGEX REPLACE "\n$" "" out "${out}")
  string(REPLACE "\n" ";" lines "${out}")
  list(GET lines 0 command)
  list(GET lines 1 machine)
  if(NOT command MATCHES "^# flipflop bench " OR NOT machine MATCHES "^# machine: .+, [0-9]+ logical processors, .*load average")
    message(FATAL_ERROR "flipflop bench ${ARGN}: no command and machine comment lines: '${command}' '${machine}'")
  endif()
  list(REMOVE_AT lines 0 1)
  list(GET lines 0 first)
  if(NOT first STREQUAL header)
    message(FATAL_ERROR "flipflop bench ${ARGN}: header is '${first}', expected '${header}'")
  endif()
  list(REMOVE_AT lines 0)
  set(${rows_var} "${lines}" PARENT_SCOPE)
endfunction()
