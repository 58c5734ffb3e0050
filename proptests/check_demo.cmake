# check_demo.cmake — ctest cli.demo: `flipflop demo` (make demo's job) exits 0,
# prints one certified row per program of each job and "all answers
# certified", and, where this flipflop has the GPU kernels (GPU=ON), the rows
# of their OpenMP build (cuda-omp) for hull3, hull2 and rt2, each certified at
# the canonical level (the reference's answer), and either flipflop:cuda rows
# or the one line saying why they did not run.
#   cmake -DFLIPFLOP=<path to flipflop> -DGPU=ON|OFF -P check_demo.cmake
execute_process(COMMAND ${FLIPFLOP} demo RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "flipflop demo exited ${rc}:\n${out}\n${err}")
endif()
if(NOT out MATCHES "\nall answers certified\n" OR out MATCHES "NOT certified")
  message(FATAL_ERROR "flipflop demo: not every answer certified:\n${out}")
endif()
string(REGEX MATCHALL "\n[^\n]*certified \\((canonical|exact)\\)" rows "${out}")
list(LENGTH rows n)
if(n LESS 28)
  message(FATAL_ERROR "flipflop demo: ${n} certified rows, expected at least 28:\n${out}")
endif()
if(GPU)
  foreach(job "hull3 ball[ ]+flipflop:cuda-omp \\(GPU ffHull\\)" "hull3 sphere[ ]+flipflop:cuda-omp \\(GPU ffHull\\)"
              "hull2 disk[ ]+flipflop:cuda-omp \\(GPU Graham\\)"
              "rt2 square w\\[0,1e-5\\][ ]+flipflop:cuda-omp \\(GPU ffRT\\)")
    if(NOT out MATCHES "\n${job}[^\n]*certified \\(canonical\\)\n")
      message(FATAL_ERROR "flipflop demo: no certified row '${job}':\n${out}")
    endif()
  endforeach()
  if(NOT out MATCHES "flipflop:cuda \\(GPU ffHull\\)[^\n]*certified \\(canonical\\)\n" AND
     NOT out MATCHES "\nflipflop:cuda not run: [^\n]+\n")
    message(FATAL_ERROR "flipflop demo: neither flipflop:cuda rows nor the reason they did not run:\n${out}")
  endif()
endif()
message(STATUS "flipflop demo: ${n} rows, all certified")
