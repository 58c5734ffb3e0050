# check_rt3_csv.cmake — ctest bench.rt3_csv: `flipflop bench rt3|dt3 --csv`
# prints the documented header and its rows in order, every row identical to
# flipflop:cpu's tetrahedra on input in general position (uniform random
# points: the exact peers CGAL and TetGen, and Qhull at this size, must
# agree), the reference included; --run with a trailing '$' chooses one
# row; --stages --csv prints the stages of a whole run (the result certified
# inside the benchmark: a failure exits non-zero). Small inputs, one run: the
# timings are not the point here.
#   cmake -DFLIPFLOP=<path to flipflop> -P check_rt3_csv.cmake
include(${CMAKE_CURRENT_LIST_DIR}/bench_csv.cmake)
set(header "name,median_s,min_s,max_s,size,identical")
foreach(job "dt3;ball;flipflop:cpu;flipflop:reference;flipflop:cuda-omp?;cgal:delaunay_triangulation_3;cgal:delaunay_triangulation_3:parallel;cgal:regular_triangulation_3;cgal:regular_triangulation_3:parallel;qhull;tetgen?"
            "rt3;cube;flipflop:cpu;flipflop:reference;flipflop:cuda-omp?;cgal:regular_triangulation_3;cgal:regular_triangulation_3:parallel")
  list(GET job 0 kind)
  list(GET job 1 dist)
  list(SUBLIST job 2 -1 want)
  flipflop_bench_rows(lines ${header} ${kind} --dist ${dist} --n 3000 --reps 1 --csv)
  set(got)
  foreach(row IN LISTS lines)
    if(NOT row MATCHES "^([^,]+),[0-9.]+,[0-9.]+,[0-9.]+,([1-9][0-9]*),1$")
      message(FATAL_ERROR "${kind} ${dist}: row '${row}' is not a successful row identical to flipflop:cpu's")
    endif()
    list(APPEND got "${CMAKE_MATCH_1}")
  endforeach()
  # NAME?: a row where this build has it (tetgen: TetGen; flipflop:cuda-omp:
  # the thrust/OpenMP build of kernels_cuda/; flipflop:cuda rows appear only
  # where nvcc built the kernels, and are not expected here)
  list(REMOVE_ITEM got flipflop:cuda flipflop:cuda:no-transfers)
  foreach(optional tetgen flipflop:cuda-omp)
    list(FIND got ${optional} has_it)
    if(has_it EQUAL -1)
      list(REMOVE_ITEM want "${optional}?")
    else()
      list(TRANSFORM want REPLACE "^${optional}\\?$" "${optional}")
    endif()
  endforeach()
  if(NOT got STREQUAL want)
    message(FATAL_ERROR "${kind}: rows '${got}', expected '${want}'")
  endif()
endforeach()
flipflop_bench_rows(lines ${header} dt3 --dist cube --n 500 --reps 1 --csv --run cgal:delaunay_triangulation_3$)
if(NOT lines MATCHES "^cgal:delaunay_triangulation_3,[^;]*$")
  message(FATAL_ERROR "--run cgal:delaunay_triangulation_3$: rows '${lines}'")
endif()
flipflop_bench_rows(lines "stage,median_s,min_s,max_s,size" rt3 --stages --dist ball --n 5000 --reps 1 --csv)
set(names)
foreach(row IN LISTS lines)
  string(REGEX MATCH "^[^,]+" name "${row}")
  list(APPEND names "${name}")
endforeach()
foreach(s "read .xyz" "read .npy" "compute: sort" "compute: insert" "compute: output" "certify" "write" "total (.npy)")
  list(FIND names "${s}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "rt3 --stages: no stage '${s}' in '${names}'")
  endif()
endforeach()
