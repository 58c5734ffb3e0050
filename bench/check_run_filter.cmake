# check_run_filter.cmake — ctest bench.run_filter: `flipflop bench --run` chooses
# rows by case-insensitive name prefix, and a prefix ending in '$' chooses the
# row of exactly that name (flipflop:cpu$ is flipflop:cpu alone, not
# flipflop:cpu:graham-insert). Small input, one run: timings are not the point.
#   cmake -DFLIPFLOP=<path to flipflop> -P check_run_filter.cmake
include(${CMAKE_CURRENT_LIST_DIR}/bench_csv.cmake)
set(header "name,median_s,min_s,max_s,size,identical")
foreach(job "FLIPFLOP:CPU;flipflop:cpu;flipflop:cpu:graham-insert"
            "flipflop:cpu$;flipflop:cpu"
            "flipflop:CPU:graham-insert$,qhull;flipflop:cpu:graham-insert;qhull")
  list(GET job 0 run)
  list(SUBLIST job 1 -1 want)
  flipflop_bench_rows(lines ${header} hull2 --dist disk --n 2000 --reps 1 --csv --run ${run})
  set(got)
  foreach(row IN LISTS lines)
    string(REGEX MATCH "^[^,]+" name "${row}")
    list(APPEND got "${name}")
  endforeach()
  if(NOT got STREQUAL want)
    message(FATAL_ERROR "--run ${run}: rows '${got}', expected '${want}'")
  endif()
endforeach()
execute_process(COMMAND ${FLIPFLOP} bench hull2 --dist disk --n 100 --reps 1 --csv --run flipflop:cp$
                RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
if(rc EQUAL 0 OR NOT err MATCHES "matches no row")
  message(FATAL_ERROR "--run flipflop:cp$ must match no row and fail (exit ${rc}: ${err})")
endif()
