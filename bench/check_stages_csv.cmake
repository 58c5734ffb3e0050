# check_stages_csv.cmake — ctest bench.stages_csv: `flipflop bench hull2|hull3
# --stages --csv` prints the documented header and the stages of a whole run
# in order (the inputs read back bit for bit and the results certified inside
# the benchmark: a failure exits non-zero and fails this test). Small inputs,
# one run: the timings are not the point here.
#   cmake -DFLIPFLOP=<path to flipflop> -P check_stages_csv.cmake
include(${CMAKE_CURRENT_LIST_DIR}/bench_csv.cmake)
foreach(job "hull3;ball;read .xyz;read .npy;compute: initial tetrahedron, inner box and ball, static filter;compute: construction rounds;compute: flip-flop;compute: canonical output;compute: witness: inner ball;compute: witness: walks;certify;certify without witness (not in the total);write;total (.npy)"
            "hull2;disk;read .xyz;read .npy;compute: throw-away;compute: sort by x;compute: split and flip-pop;compute: output;certify;write;total (.npy)")
  list(GET job 0 kind)
  list(GET job 1 dist)
  list(SUBLIST job 2 -1 stages)
  flipflop_bench_rows(lines "stage,median_s,min_s,max_s,size" ${kind} --stages --dist ${dist} --n 20000 --reps 1 --csv)
  list(LENGTH lines n)
  list(LENGTH stages want)
  if(NOT n EQUAL want)
    message(FATAL_ERROR "${kind}: expected ${want} stages, got ${n}: ${lines}")
  endif()
  set(i 0)
  foreach(s IN LISTS stages)
    list(GET lines ${i} row)
    string(REPLACE "." "\\." re "${s}")
    string(REPLACE "(" "\\(" re "${re}")
    string(REPLACE ")" "\\)" re "${re}")
    if(s MATCHES ",")  # quoted (RFC 4180)
      set(re "\"${re}\"")
    endif()
    if(NOT row MATCHES "^${re},[0-9.]+,[0-9.]+,[0-9.]+,[1-9][0-9]*$")
      message(FATAL_ERROR "${kind}: row ${i} is '${row}', expected stage '${s}'")
    endif()
    math(EXPR i "${i} + 1")
  endforeach()
endforeach()
