# consumer_test.cmake — ctest install.consumer_example (fuzz/CMakeLists.txt):
# the path a consumer takes, end to end.
#   1. cmake --install FLIPFLOP_BUILD_DIR --prefix WORK_DIR/prefix
#   2. the installed package files must not name the source or build tree
#      (the package is usable without this checkout);
#   3. configure examples/fuzz_qhull with CMAKE_PREFIX_PATH=WORK_DIR/prefix
#      (find_package(flipflop), find_package(Qhull)) with the same compiler and
#      flags as the build under test, build it;
#   4. run it for a few seeds: it must exit 0 (every run decided) and print
#      its summary. What Qhull gets wrong is reported in the test's output,
#      not a failure: Qhull is the program under test there, not flipflop.
# Arguments (-D): FLIPFLOP_BUILD_DIR EXAMPLE_SOURCE_DIR WORK_DIR
#   CMAKE_CXX_COMPILER CMAKE_C_COMPILER CXX_FLAGS LINKER_FLAGS BUILD_TYPE [SEEDS]
cmake_minimum_required(VERSION 3.18)
foreach(var FLIPFLOP_BUILD_DIR EXAMPLE_SOURCE_DIR WORK_DIR CMAKE_CXX_COMPILER)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "consumer_test.cmake: -D${var}=... is required")
  endif()
endforeach()
if(NOT DEFINED SEEDS)
  set(SEEDS 2)
endif()
if(NOT BUILD_TYPE)
  set(BUILD_TYPE Release)
endif()

function(run_step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "consumer_test: ${what} failed (${rc}):\n${out}\n${err}")
  endif()
  set(step_output "${out}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE "${WORK_DIR}")
set(prefix "${WORK_DIR}/prefix")
run_step("cmake --install" ${CMAKE_COMMAND} --install "${FLIPFLOP_BUILD_DIR}" --prefix "${prefix}")

file(GLOB package_files "${prefix}/lib*/cmake/flipflop/*.cmake")
if(NOT package_files)
  message(FATAL_ERROR "consumer_test: no flipflop package files under ${prefix}")
endif()
get_filename_component(source_root "${EXAMPLE_SOURCE_DIR}/../.." ABSOLUTE)
foreach(f ${package_files})
  file(READ "${f}" text)
  foreach(tree "${source_root}" "${FLIPFLOP_BUILD_DIR}")
    string(FIND "${text}" "${tree}" at)
    if(NOT at EQUAL -1)
      message(FATAL_ERROR "consumer_test: ${f} names ${tree}: the installed package depends on this checkout")
    endif()
  endforeach()
endforeach()

set(configure_args -S "${EXAMPLE_SOURCE_DIR}" -B "${WORK_DIR}/build"
    "-DCMAKE_PREFIX_PATH=${prefix}" "-DCMAKE_BUILD_TYPE=${BUILD_TYPE}"
    "-DCMAKE_CXX_COMPILER=${CMAKE_CXX_COMPILER}" "-DCMAKE_CXX_FLAGS=${CXX_FLAGS}"
    "-DCMAKE_EXE_LINKER_FLAGS=${LINKER_FLAGS}")
if(CMAKE_C_COMPILER)
  list(APPEND configure_args "-DCMAKE_C_COMPILER=${CMAKE_C_COMPILER}")
endif()
run_step("configuring examples/fuzz_qhull" ${CMAKE_COMMAND} ${configure_args})
run_step("building examples/fuzz_qhull" ${CMAKE_COMMAND} --build "${WORK_DIR}/build" -j 2)
run_step("running fuzz_qhull" "${WORK_DIR}/build/fuzz_qhull" --seeds ${SEEDS} --save "${WORK_DIR}")
message("${step_output}")
string(FIND "${step_output}" "fuzz_qhull: " at)
if(at EQUAL -1)
  message(FATAL_ERROR "consumer_test: fuzz_qhull printed no summary")
endif()
