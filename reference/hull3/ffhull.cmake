flipflop_reference_part(flipflop_ffhull SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/polyhedron3.cpp
  ${CMAKE_CURRENT_LIST_DIR}/rational_kernel.cpp
  ${CMAKE_CURRENT_LIST_DIR}/flip_flop_3d.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ffhull.cpp)
