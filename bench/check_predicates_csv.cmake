# check_predicates_csv.cmake — ctest bench.predicates_csv: `flipflop bench
# predicates --csv` prints the documented header and one well-formed row per
# predicate x input (every stage checked against GMP before it is timed: a
# disagreement exits non-zero and fails this test). --n 200 --reps 1 keeps it
# near 10 s (the extreme-magnitude rows in 5-7 points dominate; sanitizer
# builds run it too): the timings are not the point here.
#   cmake -DFLIPFLOP=<path to flipflop> -P check_predicates_csv.cmake
execute_process(COMMAND ${FLIPFLOP} bench predicates --n 200 --reps 1 --csv
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "flipflop bench predicates failed (${rc}): ${err}")
endif()
string(REGEX REPLACE "\n$" "" out "${out}")
string(REPLACE "\n" ";" lines "${out}")
list(GET lines 0 header)
set(want "predicate,input,flipflop_ns,static_ns,dynamic_ns,expansion_ns,cgal_epick_ns,gmp_ns,static_decides,dynamic_decides")
if(NOT header STREQUAL want)
  message(FATAL_ERROR "header is '${header}', expected '${want}'")
endif()
list(REMOVE_AT lines 0)
list(LENGTH lines n)
if(NOT n EQUAL 36)
  message(FATAL_ERROR "expected 36 rows (9 predicates x 4 inputs), got ${n}")
endif()
set(i 0)
foreach(p orient2d orient3d orient4d orient5d orient6d power2d power3d power4d power5d)
  foreach(f random near-degenerate degenerate extreme)
    list(GET lines ${i} row)
    # name, input, five timings (the CGAL one may be empty), GMP, two fractions
    if(NOT row MATCHES "^${p},${f},[0-9.]+,[0-9.]+,[0-9.]+,[0-9.]+,[0-9.]*,[0-9.]+,[01]\\.[0-9]+,[01]\\.[0-9]+$")
      message(FATAL_ERROR "malformed row ${i}: '${row}'")
    endif()
    math(EXPR i "${i} + 1")
  endforeach()
endforeach()
message(STATUS "bench predicates --csv: header and 36 rows well formed")
