# Star splaying (thesis §3.3.2, ch. 7), its pipeline from the hull of a
# recursive sample, and the strict view of a 3D hull.
flipflop_reference_part(flipflop_splay
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/star_splaying.cpp
          ${CMAKE_CURRENT_LIST_DIR}/initial_stars.cpp
          ${CMAKE_CURRENT_LIST_DIR}/strict_hull3.cpp)
