# check_predicates_csv.cmake — ctest bench.predicates_csv: `flipflop bench
# predicates --csv` prints the documented header and one well-formed row per
# predicate x input (every stage checked against GMP before it is timed: a
# disagreement exits non-zero and fails this test). --n 200 --reps 1 keeps it
# near 10 s (the extreme-magnitude rows in 5-7 points dominate; sanitizer
# builds run it too): the timings are not the point here.
#   cmake -DFLIPFLOP=<path to flipflop> -P check_predicates_csv.cmake
include(${CMAKE_CURRENT_LIST_DIR}/bench_csv.cmake)
flipflop_bench_rows(lines
  "predicate,input,flipflop_ns,static_ns,dynamic_ns,expansion_ns,cgal_epick_ns,gmp_ns,static_decides,dynamic_decides"
  predicates --n 200 --reps 1 --csv)
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
