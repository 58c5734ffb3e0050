# ctest examples.optimal_transport_2d: runs the example on 300 points and
# checks that it converged with every update certified (exit status 0, its
# summary line) and that the SVG it wrote parses as XML with one polygon per
# non-empty cell (Debian's python3).
file(REMOVE ${SVG})
execute_process(COMMAND ${EXE} --n 300 --seed 7 --svg ${SVG} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "optimal_transport_2d exited ${rc}")
endif()
if(NOT out MATCHES "converged in [0-9]+ steps.*every update certified")
  message(FATAL_ERROR "optimal_transport_2d printed no convergence line")
endif()
execute_process(COMMAND /usr/bin/python3 -c
  "import sys, xml.etree.ElementTree as E; r = E.parse(sys.argv[1]).getroot(); n = sum(1 for e in r.iter() if e.tag.endswith('polygon')); print(n); sys.exit(0 if n >= 250 else 1)"
  ${SVG} RESULT_VARIABLE prc OUTPUT_VARIABLE pout ERROR_VARIABLE perr)
if(NOT prc EQUAL 0)
  message(FATAL_ERROR "the SVG is not well-formed or has too few cells (${pout}${perr})")
endif()
