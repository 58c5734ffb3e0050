flipflop_reference_part(flipflop_twist_flip SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/twist_flip.cpp
  ${CMAKE_CURRENT_LIST_DIR}/twist_flip_input.cpp
  DEPENDS flipflop_ffhull)
