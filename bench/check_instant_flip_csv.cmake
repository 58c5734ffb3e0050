# check_instant_flip_csv.cmake — ctest bench.instant_flip_csv: `flipflop bench
# instant-flip --csv` prints the documented header and the three rows
# (flipflop:instant-flip, flipflop:reference:rt+1, cgal:regular_triangulation),
# each with identical = 1: the in-place update equals both fresh builds, in
# d = 2 and 3 and for a small and a large step. Small inputs, one run.
#   cmake -DFLIPFLOP=<path to flipflop> -P check_instant_flip_csv.cmake
include(${CMAKE_CURRENT_LIST_DIR}/bench_csv.cmake)
foreach(job "2;3000;0.01" "2;2000;1" "3;1500;0.01" "3;1000;1" "4;300;0.1")
  list(GET job 0 dim)
  list(GET job 1 n)
  list(GET job 2 step)
  flipflop_bench_rows(lines "name,median_s,min_s,max_s,size,identical"
                      instant-flip --dim ${dim} --n ${n} --step ${step} --reps 1 --csv)
  set(want "flipflop:instant-flip;flipflop:reference:rt\\+1;cgal:regular_triangulation")
  list(LENGTH lines nrows)
  if(NOT nrows EQUAL 3)
    message(FATAL_ERROR "instant-flip d ${dim}: expected 3 rows, got ${nrows}: ${lines}")
  endif()
  set(i 0)
  foreach(name IN LISTS want)
    list(GET lines ${i} row)
    if(NOT row MATCHES "^${name},[0-9.]+,[0-9.]+,[0-9.]+,[1-9][0-9]*,1$")
      message(FATAL_ERROR "instant-flip d ${dim} n ${n} step ${step}: row ${i} is '${row}' (expected ${name}, identical = 1)")
    endif()
    math(EXPR i "${i} + 1")
  endforeach()
endforeach()
