flipflop_reference_part(flipflop_hull3 SOURCES ${CMAKE_CURRENT_LIST_DIR}/hull3.cpp
                        DEPENDS flipflop_ffhull flipflop_splay flipflop_twist_flip)
